#!/usr/bin/env node
// The browser edition in headless Chromium (README, "Kinds of test": web), one browser for every page of a rasterizer:
//  - every lab's page (the starter, as the site ships it) loads with no console error and draws its first case; a
//    screenshot of it is kept; with --native its self-check gives 0 points (once: the not-done colour is the same on
//    every rasterizer); it fetches the shared data packages it declares and no other, each sent once across the labs;
//  - every lab's reference page draws every public case, each within its golden image's tolerance, printing the
//    largest channel difference and the share of pixels over the tolerance; its self-check gives full marks;
//  - with --editor: one TODO undone (gsv-make-starters --undone, opened in the editor) loses exactly that TODO's cases;
//    a broken edit shows file:line and keeps the picture, fixing it restores it, a reload keeps the edit, and the
//    downloaded zip is what gsv-grade --submission then grades.
// With --native, each starter's self-check runs and its table is held against gsv-grade --self-check --profile es's on
// the same files.
// Usage: check_pages.js --base URL --out DIR --rasterizer NAME --kit ROOT --site WEB_BUILD --bin BIN [--editor] [--native] [--labs lab01,lab02|none]
'use strict';
const fs = require('fs');
const path = require('path');
const { execFileSync } = require('child_process');
const { chromium } = require(path.join(__dirname, '../../web/node_modules/playwright-core'));

const args = {};
for (let i = 2; i < process.argv.length; i++) {
  const a = process.argv[i];
  if (a === '--editor') args.editor = true;
  else if (a === '--native') args.native = true;
  else args[a.replace(/^--/, '')] = process.argv[++i];
}
const rasterizers = {
  // Mesa's llvmpipe (the goldens' own rasterizer) through ANGLE's GL back end, under Xvfb.
  'angle-llvmpipe': ['--use-gl=angle', '--use-angle=gl', '--ignore-gpu-blocklist'],
  // Chromium's own software rasterizer, independent of llvmpipe.
  'swiftshader': ['--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
};
const out = path.join(args.out, args.rasterizer);
fs.mkdirSync(out, { recursive: true });
// Every lab of the kit's list (scripts/kit_labs.py), unless --labs names some (or none).
const labs = args.labs === 'none' ? [] : (args.labs || execFileSync('python3',
  [path.join(args.kit, 'scripts', 'kit_labs.py'), '--kit', args.kit, '--ids'], { encoding: 'utf8' }).trim()).split(',');
let failures = 0, checks = 0;
function check(ok, line) {
  checks++;
  if (!ok) failures++;
  console.log((ok ? 'ok   ' : 'FAIL ') + args.rasterizer + ' ' + line);
}

async function openPage(context, url) {
  const page = await context.newPage();
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push('console error: ' + m.text()); });
  page.on('pageerror', (e) => problems.push('page error: ' + e.message));
  const t0 = Date.now();
  await page.goto(url);
  await page.waitForFunction(() => window.gsvPage && (window.gsvPage.frames > 0 || window.gsvPage.failed), null,
                             { timeout: 120000 });
  const state = await page.evaluate(() => ({ failed: window.gsvPage.failed, status: document.getElementById('status').textContent }));
  return { page, problems, state, ms: Date.now() - t0 };
}

// The canvas's pixels as the page drew them (preserveDrawingBuffer), as a data URL, and whether they are one colour.
async function canvasPixels(page) {
  return page.evaluate(() => {
    const canvas = document.getElementById('canvas');
    const copy = document.createElement('canvas');
    copy.width = canvas.width;
    copy.height = canvas.height;
    const c2d = copy.getContext('2d');
    c2d.drawImage(canvas, 0, 0);
    const data = c2d.getImageData(0, 0, copy.width, copy.height).data;
    let flat = true, black = true;
    for (let i = 0; i < data.length; i += 4) {
      if (data[i] !== data[0] || data[i + 1] !== data[1] || data[i + 2] !== data[2]) flat = false;
      if (data[i] || data[i + 1] || data[i + 2]) black = false;
    }
    return { url: copy.toDataURL(), flat, black };
  });
}

// gsv-grade's table rows (lab, check, TODO, status, points), without the details, whose numbers differ by rasterizer
// ("identical" natively, "max diff 1" through ANGLE).
function tableRows(table) {
  return table.split('\n').filter((l) => /^lab\d\d  /.test(l)).map((l) => l.trim().split(/\s{2,}/).slice(0, 5).join(' | '));
}
// A case the page cannot draw (lab 05's L05-T2 needs ES 3.1; WebGL 2 is 3.0) is "unsupported" there and graded natively
// at its own ES version: such rows are left out of both tables, every other row must be the same.
function sameRows(native, inPage) {
  const unsupported = new Set(tableRows(inPage).filter((r) => r.split(' | ')[3] === 'unsupported').map((r) => r.split(' | ')[1]));
  const keep = (rows) => rows.filter((r) => !unsupported.has(r.split(' | ')[1]));
  return JSON.stringify(keep(tableRows(native))) === JSON.stringify(keep(tableRows(inPage)));
}

function gradeNatively(options, name) {
  const grades = path.join(out, name + '-grades');
  fs.rmSync(grades, { recursive: true, force: true });
  try {
    return execFileSync(path.join(args.bin, 'gsv-grade'), [...options, '--no-timing', '--out', grades],
                        { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  } catch (e) {
    return String(e.stdout || '') + String(e.stderr || '');
  }
}

async function selfCheck(page) {
  return page.evaluate(() => window.gsvSelfCheck.run(''));
}

function printCases(lab, result) {
  for (const r of result.results) {
    const share = r.total_pixels ? (100 * r.differing_pixels / r.total_pixels).toFixed(3) : '-';
    console.log('     ' + args.rasterizer + ' ' + lab + ' ' + r.name.padEnd(16) + ' ' + r.status.padEnd(12) +
                ' max channel diff ' + String(r.max_channel_diff).padStart(3) + ', over tolerance (' +
                r.tolerance_max_channel_diff + ') ' + share + '% of pixels (allowed ' +
                (100 * r.tolerance_max_differing_fraction).toFixed(2) + '%)');
  }
}

async function starterPage(context, lab) {
  const first = JSON.parse(fs.readFileSync(path.join(args.kit, 'grader/cases', lab + '.json'), 'utf8')).cases[0].name;
  const { page, problems, state, ms } = await openPage(context, args.base + '/site/' + lab + '/index.html?case=' + first);
  check(!state.failed, lab + ' page loads and draws its first case (' + first + ') in ' + ms + ' ms' + (state.failed ? ': ' + state.failed : ''));
  const pixels = await canvasPixels(page);
  // A starter may paint the whole picture magenta (nothing done yet): drawn, if not yet a picture.
  check(!pixels.black, lab + ' first frame is drawn (' + (pixels.flat ? 'one colour: the starter\'s' : 'a picture') + ')');
  await page.screenshot({ path: path.join(out, lab + '-page.png'), fullPage: true });
  await editorTabs(page, lab);
  await desktopOnly(page, lab);
  await pageWeight(page, lab);
  // The starter's self-check draws every case; once (with --native, against gsv-grade's table) is enough: its
  // not-done colour is the same on every rasterizer.
  if (!args.native) {
    check(problems.length === 0, lab + ' no console error' + (problems.length ? ': ' + problems.join('; ') : ''));
    await page.close();
    return;
  }
  const result = await selfCheck(page);
  check(result.score === 0 && result.max_score > 0, lab + ' starter: self-check ' + result.score + ' of ' + result.max_score + ' points');
  {
    const native = gradeNatively(['--self-check', '--profile', 'es', '--labs', lab], lab + '-starter');
    check(sameRows(native, result.table), lab + ' starter: the page\'s table has gsv-grade --self-check --profile es\'s rows' +
          (sameRows(native, result.table) ? '' : ':\n' + result.table + '\nnative:\n' + native));
  }
  check(problems.length === 0, lab + ' no console error' + (problems.length ? ': ' + problems.join('; ') : ''));
  await page.close();
}

// The page's weight as the browser fetched it from scripts/serve.py (gzip), against the files' own sizes: every file
// the page and its lab loaded, the shared ones (the editor, the pages' scripts) counted too, and what a first visit to
// it sends (each file's compressed body, as kept where it came back unchanged).
// The shared data packages (a folder of data/ each, and the font: cmake/web.cmake) are fetched by the labs that
// declare them (the page's data-packages) and by no other; one that an earlier lab's page fetched is asked for again
// only to be told it is unchanged (a 304), not sent again.
const packagesFetched = new Set();
async function pageWeight(page, lab) {
  const w = await page.evaluate(() => {
    const entries = [...performance.getEntriesByType('navigation'), ...performance.getEntriesByType('resource')];
    const wasm = entries.find((e) => /\.wasm$/.test(e.name));
    const packages = entries.filter((e) => /\/shared\/[^/]+\.data$/.test(e.name)).map((e) => ({
      name: e.name.replace(/^.*\/shared\/|\.data$/g, ''), sent: e.transferSize, size: e.decodedBodySize,
      compressed: e.encodedBodySize }));
    return { declared: (document.body.dataset.packages || '').split(' ').filter((n) => n), packages,
             files: entries.length, sent: entries.reduce((s, e) => s + e.transferSize, 0),
             size: entries.reduce((s, e) => s + e.decodedBodySize, 0),
             firstVisit: entries.reduce((s, e) => s + e.encodedBodySize, 0),
             wasmSent: wasm ? wasm.encodedBodySize : 0, wasmSize: wasm ? wasm.decodedBodySize : 0 };
  });
  const mib = (n) => (n / 1048576).toFixed(2) + ' MiB';
  check(w.wasmSize > 0 && w.wasmSent < w.wasmSize, lab + ' page weight: ' + mib(w.size) + ' in ' + w.files + ' files, ' +
        mib(w.sent) + ' sent compressed (a first visit ' + mib(w.firstVisit) + '; its WebAssembly ' + mib(w.wasmSize) + ', ' +
        mib(w.wasmSent) + ' sent)');
  const loaded = w.packages.map((p) => p.name);
  const undeclared = loaded.filter((n) => !w.declared.includes(n));
  const missing = w.declared.filter((n) => !loaded.includes(n));
  check(undeclared.length === 0 && missing.length === 0 && loaded.length === new Set(loaded).size,
        lab + ' loads the data packages it declares (' + (w.declared.join(', ') || 'none') + ')' +
        (undeclared.length ? ', and ' + undeclared.join(', ') + ', which it does not' : '') +
        (missing.length ? '; not ' + missing.join(', ') : '') + (loaded.length > new Set(loaded).size ? '; one twice' : ''));
  for (const p of w.packages) {
    // A 304 sends its headers only (the entry's responseStatus is the kept response's 200 either way).
    const revalidated = p.sent > 0 && p.sent < Math.min(16384, p.compressed);
    const earlier = packagesFetched.has(p.name);
    check(p.size > 0 && (earlier ? revalidated : !revalidated && p.sent > 0),
          lab + ' data package ' + p.name + ': ' + mib(p.size) + ' (' + mib(p.compressed) + ' compressed), ' +
          (revalidated ? 'kept from an earlier page (a 304: ' + p.sent + ' bytes)' : mib(p.sent) + ' sent') +
          (earlier ? (revalidated ? '' : ': an earlier page fetched it already') : (revalidated ? ': no earlier page fetched it' : '')));
    packagesFetched.add(p.name);
  }
}

// Cases past WebGL 2's ES 3.0 (lab 05's compute shaders, "feature": "compute") are named under the self-check with the points they hold, and
// marked in the case list; a lab without them says nothing there.
async function desktopOnly(page, lab) {
  const cases = JSON.parse(fs.readFileSync(path.join(args.kit, 'grader/cases', lab + '.json'), 'utf8')).cases;
  // A case past ES 3.0 by its "es" or by a "feature" WebGL 2 lacks (lab 05's "compute": ES 3.1's).
  const desktop = cases.filter((c) => (c.es && c.es !== '3.0') || c.feature === 'compute');
  const sum = (list) => list.reduce((s, c) => s + (c.points === undefined ? 1 : c.points), 0);
  const seen = await page.evaluate(() => ({ note: document.getElementById('self-check-desktop').textContent,
    marked: Array.from(document.getElementById('case').options).filter((o) => /desktop only/.test(o.textContent)).map((o) => o.value) }));
  const ok = desktop.length
    ? seen.note.startsWith(sum(desktop) + ' of ' + sum(cases) + ' points') && desktop.every((c) => seen.note.includes(c.name)) &&
      seen.marked.join() === desktop.map((c) => c.name).join()
    : seen.note === '' && seen.marked.length === 0;
  check(ok, lab + ' desktop-only cases: ' + (desktop.length ? seen.note : 'none, and none said'));
}

// The editor's tabs: each file with a TODO names its TODO ids on its tab; a compute shader (the page has none) is
// marked as not compiled here; the editor opens on a file with a TODO that the page compiles.
async function editorTabs(page, lab) {
  const tabs = await page.evaluate(() => window.gsvEditor.files().map((f) => ({
    name: f.name, todos: (f.starter.match(/TODO\((L\d\d-T\d+)\)/g) || []).map((t) => t.slice(5, -1)),
    tab: f.tab.textContent, todoClass: f.tab.classList.contains('todo'), notCompiled: f.tab.classList.contains('not-compiled'),
    selected: f.tab.getAttribute('aria-selected') === 'true' })));
  const withTodo = tabs.filter((t) => t.todos.length);
  const named = withTodo.every((t) => t.todoClass && t.todos.every((id) => t.tab.includes(id)));
  const unmarked = tabs.filter((t) => !t.todos.length && t.todoClass);
  check(withTodo.length > 0 && named && unmarked.length === 0,
        lab + ' editor: the ' + withTodo.length + ' of ' + tabs.length + ' tabs with a TODO name it (' +
        withTodo.map((t) => t.tab).join(', ') + ')');
  const comp = tabs.filter((t) => /\.comp$/.test(t.name));
  check(comp.every((t) => t.notCompiled) && tabs.filter((t) => t.notCompiled).length === comp.length,
        lab + ' editor: ' + (comp.length ? comp.map((t) => t.name).join(', ') + ' marked as not compiled in the page' : 'no compute shader to mark'));
  const open = tabs.find((t) => t.selected);
  check(open && open.todos.length > 0 && !open.notCompiled, lab + ' editor: opens on ' + (open ? open.name : 'nothing') + ', a file with a TODO the page compiles');
}

async function solutionPage(context, lab) {
  const { page, problems, state } = await openPage(context, args.base + '/lecturer/' + lab + '/index.html');
  check(!state.failed, lab + ' reference page starts' + (state.failed ? ': ' + state.failed : ''));
  check(!(await canvasPixels(page)).flat, lab + ' reference page draws a picture, not one flat colour');
  if (args.editor) await everyControl(page, lab);
  let result = await selfCheck(page);
  fs.writeFileSync(path.join(out, lab + '-solution-table.txt'), result.table || result.error);
  await page.screenshot({ path: path.join(out, lab + '-reference-self-check.png'), fullPage: true });
  const desktopOnly = result.results.filter((r) => r.status === 'unsupported');
  check(result.score === result.max_score - desktopOnly.reduce((s, r) => s + r.max_points, 0),
        lab + ' reference: self-check ' + result.score + ' of ' + result.max_score + ' points' +
        (desktopOnly.length ? ' (' + desktopOnly.map((r) => r.name).join(', ') + ': desktop only)' : ''));
  printCases(lab, result);
  for (const r of result.results) if (r.status !== 'passed' && r.status !== 'unsupported') check(false, lab + ' ' + r.name + ': ' + r.detail);
  check(problems.length === 0, lab + ' reference page: no console error' + (problems.length ? ': ' + problems.join('; ') : ''));
  await page.close();
}

// Every control of a lab's page either changes the picture or says why not: each in turn is set to another value (the
// next choice, the other state, a quarter of its range away from either end), the page left to draw until it is at
// rest, and the picture compared; a control greyed must carry its reason, and one whose change draws the same picture
// must have said something on the status line. Each is then set back.
async function everyControl(page, lab) {
  const results = await page.evaluate(async () => {
    const $ = (id) => document.getElementById(id);
    const frame = () => new Promise((resolve) => requestAnimationFrame(resolve));
    const atRest = async () => {
      for (let i = 0; i < 2000 && (window.gsvPage.dirty || Module.drawAgain()); i++) await frame();
      await frame();
      await frame();
    };
    const picture = () => $('canvas').toDataURL();
    const set = async (input, value) => {
      if (input.type === 'checkbox') input.checked = value;
      else input.value = value;
      input.dispatchEvent(new Event(input.type === 'range' ? 'input' : 'change'));
      await atRest();
    };
    const other = (input) => {
      if (input.type === 'checkbox') return !input.checked;
      if (input.tagName === 'SELECT') return input.options[(input.selectedIndex + 1) % input.options.length].value;
      if (input.type === 'range') {
        const min = Number(input.min), max = Number(input.max), v = Number(input.value);
        const to = v > (min + max) / 2 ? min + 0.25 * (max - min) : min + 0.75 * (max - min);
        return String(input.step === '1' ? Math.round(to) : to);
      }
      // A vec3 as "x,y,z": its components rotated (x,y,z -> y,z,x), or where they are all equal, 0.8 of each: either
      // stays within a range that holds the value.
      const xyz = input.value.split(',').map(Number);
      if (xyz.length === 3 && xyz.every((x) => isFinite(x)))
        return (xyz[0] === xyz[1] && xyz[1] === xyz[2] ? xyz.map((x) => (x ? 0.8 * x : 0.1)) : [xyz[1], xyz[2], xyz[0]]).join(',');
      return null;  // a file by its path: there is no other file to offer it
    };
    await atRest();
    const out = [];
    for (const row of document.querySelectorAll('#controls .param')) {
      const input = row.querySelector('input, select');
      const why = row.querySelector('.why').textContent;
      if (input.disabled) {
        out.push({ name: input.name, greyed: true, why });
        continue;
      }
      const was = input.type === 'checkbox' ? input.checked : input.value;
      const to = other(input);
      if (to === null) {
        out.push({ name: input.name, skipped: 'a file path: ' + input.value });
        continue;
      }
      const before = picture(), statusBefore = $('status').textContent;
      await set(input, to);
      const changed = picture() !== before;
      const status = $('status').textContent;
      out.push({ name: input.name, to: String(to), changed, said: status !== statusBefore ? status : '' });
      await set(input, was);
    }
    return out;
  });
  const silent = results.filter((r) => (r.greyed && !r.why) || (!r.greyed && !r.skipped && !r.changed && !r.said));
  const greyed = results.filter((r) => r.greyed).map((r) => r.name + ' (' + r.why + ')');
  const said = results.filter((r) => !r.greyed && !r.changed && r.said).map((r) => r.name + '=' + r.to + ': ' + r.said);
  check(silent.length === 0 && results.length > 0,
        lab + ' every control changes the picture or says why not: ' + results.filter((r) => r.changed).length + ' of ' +
        results.length + ' change it' + (greyed.length ? '; greyed: ' + greyed.join(', ') : '') +
        (said.length ? '; said: ' + said.join('; ') : '') +
        (silent.length ? '; SILENT: ' + silent.map((r) => r.name + (r.greyed ? ' (greyed, no reason)' : '=' + r.to)).join(', ') : ''));
  return results;
}

// The page a student works in, at 1280x800: the sheet's TODO table above the editor (an id opens the file that holds
// it), the picture in view beside the editor, one TODO's self-check a case at a time with its progress and its points
// on the TODO's row, and the compare slider (yours left of it, the golden right).
async function studentsPage(context, lab) {
  const { page, problems } = await openPage(context, args.base + '/site/' + lab + '/index.html');
  await page.setViewportSize({ width: 1280, height: 800 });
  await page.waitForFunction(() => document.querySelectorAll('#todo-table tr[data-todo]').length > 0, null, { timeout: 10000 });
  const rows = await page.evaluate(() => Array.from(document.querySelectorAll('#todo-table tr[data-todo]')).map((r) => r.dataset.todo));
  const cases = JSON.parse(fs.readFileSync(path.join(args.kit, 'grader/cases', lab + '.json'), 'utf8')).cases;
  const caseTodos = [...new Set(cases.map((c) => c.todo))];
  check(caseTodos.every((t) => rows.includes(t)), lab + ' sheet: the TODO table above the editor has a row for each TODO the cases check (' + rows.join(', ') + ')');
  const sheetTables = await page.evaluate(() => document.querySelectorAll('#sheet-text table').length);
  check(sheetTables > 0, lab + ' sheet: the lab sheet is there, rendered (' + sheetTables + ' tables)');
  const last = rows[rows.length - 1];
  await page.click('#todo-table tr[data-todo="' + last + '"] a');
  const opened = await page.evaluate((id) => {
    const f = window.gsvEditor.files().find((g) => g.tab.getAttribute('aria-selected') === 'true');
    return f && f.todos.includes(id) ? f.name : null;
  }, last);
  check(!!opened, lab + ' sheet: ' + last + ' in the TODO table opens ' + (opened || 'no file that holds it'));
  // The editor's last line on screen, and the picture too.
  await page.evaluate(() => document.getElementById('code').scrollIntoView({ block: 'end' }));
  const box = await page.evaluate(() => {
    const r = document.getElementById('canvas').getBoundingClientRect();
    return { top: Math.round(r.top), bottom: Math.round(r.bottom), width: Math.round(r.width), height: window.innerHeight };
  });
  await page.screenshot({ path: path.join(out, lab + '-student-1280x800.png') });
  check(box.width > 0 && box.top >= 0 && box.bottom <= box.height, lab + ' at 1280x800, editing: the picture in view (its top ' +
        box.top + ', its bottom ' + box.bottom + ' of ' + box.height + ' px)');
  // One TODO's self-check, a case at a time: the status line says each step.
  const todo = rows[0];
  const todoCases = cases.filter((c) => c.todo === todo && (c.visibility || 'public') === 'public').map((c) => c.name);
  await page.evaluate(() => {
    window.statusLines = [];
    new MutationObserver(() => window.statusLines.push(document.getElementById('status').textContent))
      .observe(document.getElementById('status'), { childList: true, characterData: true, subtree: true });
  });
  const result = await page.evaluate((id) => window.gsvSelfCheck.check(id).then((r) => ({
    names: r.results.map((x) => x.name), score: r.score, max: r.max_score })), todo);
  const steps = await page.evaluate((id) => window.statusLines.filter((l) => l.startsWith('Self-check of ' + id + ': ') && / of \d+ cases/.test(l)).length, todo);
  const cell = await page.evaluate((id) => document.querySelector('#todo-table tr[data-todo="' + id + '"] .todo-result').textContent, todo);
  check(result.names.join() === todoCases.join() && steps === todoCases.length && cell === result.score + ' / ' + result.max,
        lab + ' self-check of ' + todo + ' alone: its ' + todoCases.length + ' cases (' + result.names.join(', ') + '), ' + steps +
        ' steps said, ' + cell + ' on its row');
  // The compare slider over the first graded case.
  await page.evaluate((name) => window.gsvPage.pickCase(name), cases[0].name);
  await page.click('#compare-button');
  await page.evaluate(() => { const s = document.getElementById('compare-at'); s.value = '30'; s.dispatchEvent(new Event('input')); });
  const cut = await page.evaluate(() => ({ shown: !document.getElementById('compare-slider').hidden,
    clip: document.getElementById('overlay').style.clipPath, overlay: !document.getElementById('overlay').hidden }));
  await page.screenshot({ path: path.join(out, lab + '-compare-slider.png') });
  check(cut.shown && cut.overlay && /inset\(0(px)? 0(px)? 0(px)? 30%\)/.test(cut.clip), lab + ' compare: the golden cut at the slider (' + cut.clip + ')');
  await page.click('#compare-button');
  const composite = await page.evaluate(() => document.getElementById('overlay').classList.contains('composite') &&
    getComputedStyle(document.getElementById('canvas')).display === 'none' && document.getElementById('compare-slider').hidden);
  check(composite, lab + ' compare: then yours | golden | difference in the picture\'s place');
  await page.click('#compare-button');
  check(problems.length === 0, lab + ' student\'s page: no console error' + (problems.length ? ': ' + problems.join('; ') : ''));
  await page.close();
}

// Lab 05's particle count: a slider in equal ratios (1 to 16,777,216), and at its top one line naming the value the page
// cannot hold, the last values that drew back and drawing.
async function particleLimit(context) {
  const { page, problems, ms } = await openPage(context, args.base + '/site/lab05/index.html');
  // With no case asked for, the page opens on the case file's "page_case" (abc: 65,536 particles, not the million).
  const opened = await page.evaluate(() => ({ select: document.getElementById('case').value,
    particles: JSON.parse(Module.states()).find((s) => s.name === 'particles').value }));
  check(opened.select === 'abc' && opened.particles === '65536', 'lab05 opens on its page case: ' + opened.select + ', ' +
        opened.particles + ' particles, its first frame in ' + ms + ' ms');
  // Its defaults (t = 2, h = 0.05) are 40 steps, and a frame takes at most 32: the page draws on until the picture is
  // at its time, with nothing else changed.
  await page.waitForFunction(() => !Module.drawAgain(), null, { timeout: 20000 }).catch(() => {});
  const caught = await page.evaluate(() => ({ frames: window.gsvPage.frames, behind: Module.drawAgain() }));
  check(caught.frames >= 2 && !caught.behind, 'lab05 draws on to its time by itself: ' + caught.frames + ' frames, ' +
        (caught.behind ? 'still behind' : 'at its time'));
  const max = await page.evaluate(() => {
    const input = document.getElementById('param-particles');
    input.value = input.max;
    input.dispatchEvent(new Event('input'));
    return input.max;
  });
  // The particles are made at the next frame: its line is the refusal.
  await page.waitForFunction(() => /more memory/.test(document.getElementById('status').textContent), null, { timeout: 30000 })
    .catch(() => {});
  const slider = { max, status: await page.evaluate(() => document.getElementById('status').textContent) };
  const frames = await page.evaluate(() => window.gsvPage.frames);
  await page.evaluate(() => window.gsvPage.changed(''));
  await page.waitForFunction((n) => window.gsvPage.frames > n, frames, { timeout: 30000 }).catch(() => {});
  const after = await page.evaluate(() => ({ frames: window.gsvPage.frames, states: Module.states() }));
  const particles = JSON.parse(after.states).find((s) => s.name === 'particles').value;
  check(/particles=16777216: more memory than the page can hold/.test(slider.status) && after.frames > frames && particles !== '16777216',
        'lab05 at the particle slider\'s top (' + slider.max + ' steps): "' + slider.status + '", then drawing with ' + particles + ' particles');
  check(problems.length === 0, 'lab05 particle limit: no console error' + (problems.length ? ': ' + problems.join('; ') : ''));
  await page.close();
}

// One TODO undone in the reference loses that TODO's cases and no other.
async function oneTodoUndone(context, lab, todo) {
  const dir = path.join(out, 'undone-' + todo);
  execFileSync(path.join(args.bin, 'gsv-make-starters'), ['--undone', todo, '--to', dir]);
  const { page } = await openPage(context, args.base + '/lecturer/' + lab + '/index.html');
  const shaders = fs.readdirSync(dir).filter((n) => /\.(vert|frag|glsl|comp)$/.test(n));
  await page.setInputFiles('#open', shaders.map((n) => path.join(dir, n)));
  await page.waitForFunction(() => /^Opened/.test(document.getElementById('status').textContent));
  await page.waitForTimeout(800);  // opened files rebuild at once; then a frame drawn from them
  const result = await selfCheck(page);
  const lost = result.results.filter((r) => r.status !== 'passed').map((r) => r.name + '(' + r.todo + ')');
  check(result.results.some((r) => r.todo === todo && r.status !== 'passed') &&
        result.results.every((r) => r.todo !== todo || r.status !== 'passed'),
        lab + ' ' + todo + ' undone loses every case of ' + todo + ': ' + lost.join(', '));
  // The same files graded natively (gsv-grade --self-check --profile es): the same rows, so any other case lost is
  // lost there too (one that draws with the undone code, such as Gooch shading under a later TODO's case).
  const submission = path.join(out, 'undone-' + todo + '-submission');
  const folder = fs.readdirSync(path.join(args.kit, 'solutions')).find((d) => d.startsWith(lab + '_'));
  fs.rmSync(submission, { recursive: true, force: true });
  fs.mkdirSync(path.join(submission, 'labs'), { recursive: true });
  fs.cpSync(dir, path.join(submission, 'labs', folder), { recursive: true });
  const native = gradeNatively(['--submission', submission, '--self-check', '--profile', 'es', '--labs', lab], 'undone-' + todo);
  check(sameRows(native, result.table), lab + ' ' + todo + ' undone: the page\'s table has gsv-grade --self-check\'s rows' +
        (sameRows(native, result.table) ? '' : ':\n' + result.table + '\nnative:\n' + native));
  await page.evaluate(() => localStorage.clear());
  await page.close();
}

// One TODO at a time in the page: for every public case, the reference with every TODO left as the starter has it but
// the case's own and those it declares as needs (gsv-make-starters --done) passes the case, as natively
// (test_grader_one_todo.cpp). A lab's C++ TODO left undone is its starter page (built from labs/); one page per lab and
// kind, the files of each set of TODOs opened in turn, each case checked alone.
async function oneTodoAtATime(context, lab) {
  const cases = JSON.parse(fs.readFileSync(path.join(args.kit, 'grader/cases', lab + '.json'), 'utf8')).cases
    .filter((c) => (c.visibility || 'public') === 'public');
  const folder = fs.readdirSync(path.join(args.kit, 'solutions')).find((d) => d.startsWith(lab + '_'));
  const cppTodos = new Set();
  for (const n of fs.readdirSync(path.join(args.kit, 'solutions', folder)).filter((n) => /\.(cpp|h)$/.test(n)))
    for (const m of fs.readFileSync(path.join(args.kit, 'solutions', folder, n), 'utf8').matchAll(/\/\/@solution (L\d\d-T\d+)/g)) cppTodos.add(m[1]);
  const groups = new Map();
  for (const c of cases) {
    const done = [...new Set([c.todo, ...(c.needs || [])])].sort().join(',');
    if (!groups.has(done)) groups.set(done, []);
    groups.get(done).push(c.name);
  }
  const pages = new Map();
  const failed = [];
  let checked = 0;
  for (const [done, names] of groups) {
    const starterCpp = [...cppTodos].some((t) => !done.split(',').includes(t));
    const url = args.base + (starterCpp ? '/site/' + lab + '/index.html' : '/lecturer/' + lab + '/index.html');
    if (!pages.has(url)) pages.set(url, (await openPage(context, url)).page);
    const page = pages.get(url);
    const dir = path.join(out, 'done-' + lab + '-' + done.replace(/,/g, '+'));
    fs.rmSync(dir, { recursive: true, force: true });
    execFileSync(path.join(args.bin, 'gsv-make-starters'), ['--done', done, '--to', dir]);
    const shaders = fs.readdirSync(dir).filter((n) => /\.(vert|frag|glsl|comp)$/.test(n));
    await page.evaluate(() => { document.getElementById('status').textContent = ''; });
    await page.setInputFiles('#open', shaders.map((n) => path.join(dir, n)));
    await page.waitForFunction(() => /^Opened/.test(document.getElementById('status').textContent));
    await page.waitForTimeout(800);  // opened files rebuild at once; then a frame drawn from them
    for (const name of names) {
      const result = await page.evaluate((n) => window.gsvSelfCheck.run(n), name);
      const r = (result.results || [])[0];
      ++checked;
      if (!r || (r.status !== 'passed' && r.status !== 'unsupported'))
        failed.push(name + ' with only ' + done + ' done: ' + (r ? r.status + ', ' + r.detail : result.error));
    }
  }
  for (const page of pages.values()) {
    await page.evaluate(() => localStorage.clear());
    await page.close();
  }
  check(failed.length === 0, lab + ' one TODO at a time: ' + checked + ' cases, each with only its TODO and its needs done, in ' +
        groups.size + ' sets' + (failed.length ? ':\n  ' + failed.join('\n  ') : ''));
}

// A known mistake made in the page (lab 01's normal left in the model's space): the page's self-check names it, as
// gsv-grade's self-check does, with the mistake's picture beside the student's and in compare's fourth view.
async function knownMistake(context, lab, name) {
  const spec = JSON.parse(fs.readFileSync(path.join(args.kit, 'tests/mutants', lab + '.json'), 'utf8'));
  const mistake = spec.mutants.find((m) => m.name === name);
  const folder = fs.readdirSync(path.join(args.kit, 'solutions')).find((d) => d.startsWith(lab + '_'));
  const dir = path.join(out, 'mistake-' + lab);
  fs.rmSync(dir, { recursive: true, force: true });
  fs.mkdirSync(dir, { recursive: true });
  const shaders = fs.readdirSync(path.join(args.kit, 'solutions', folder)).filter((n) => /\.(vert|frag|glsl|comp)$/.test(n));
  for (const n of shaders) {
    let text = fs.readFileSync(path.join(args.kit, 'solutions', folder, n), 'utf8');
    if (n === mistake.file) text = text.replace(mistake.find, mistake.replace);
    fs.writeFileSync(path.join(dir, n), text);
  }
  const { page } = await openPage(context, args.base + '/lecturer/' + lab + '/index.html');
  await page.setInputFiles('#open', shaders.map((n) => path.join(dir, n)));
  await page.waitForFunction(() => /^Opened/.test(document.getElementById('status').textContent));
  await page.waitForTimeout(800);  // opened files rebuild at once; then a frame drawn from them
  const result = await selfCheck(page);
  const named = result.results.filter((r) => r.mistake === mistake.says);
  check(named.length > 0 && named.every((r) => r.mistake_todo === mistake.todo && r.mistake_picture),
        lab + ' ' + mistake.todo + ' mistake in the page: named on ' + named.map((r) => r.name).join(', ') +
        ' (' + result.results.filter((r) => r.status !== 'passed').length + ' cases failing)');
  check(result.table.includes(mistake.says), lab + ' the page\'s table says what went wrong');
  check(await page.evaluate(() => document.querySelector('#self-check-rows .mistake') !== null),
        lab + ' the page shows what went wrong beside the pictures');
  await page.screenshot({ path: path.join(out, lab + '-known-mistake-self-check.png'), fullPage: true });
  const compareWidth = await page.evaluate((c) => new Promise((done) => {
    const img = new Image();
    img.onload = () => done(img.width);
    img.src = window.gsvSelfCheck.compareUrl(c);
  }), named.length ? named[0].name : 'stretched');
  check(compareWidth > 4 * 256, lab + ' compare in the page has the mistake\'s picture as a fourth view (' + compareWidth + ' px wide)');
  await page.evaluate(() => localStorage.clear());
  await page.close();
}

// The editor: a broken edit, its fix, a reload, and the download graded by gsv-grade.
async function editor(context, lab) {
  const { page } = await openPage(context, args.base + '/lecturer/' + lab + '/index.html');
  await page.evaluate(() => localStorage.clear());
  const before = (await canvasPixels(page)).url;
  // A fragment shader the student writes in (one with a TODO), so the picture depends on it.
  const file = await page.evaluate(() => window.gsvEditor.files().find((f) => /\.frag$/.test(f.name) && /TODO\(/.test(f.starter)).name);
  const original = await page.evaluate((name) => window.gsvEditor.files().find((f) => f.name === name).doc.getValue(), file);
  // A line that does not compile, after the first line of main().
  const lines = original.split('\n');
  const at = lines.findIndex((l) => /void main\(/.test(l)) + 1;
  lines.splice(at + 1, 0, '    this is not GLSL;');
  const broken = lines.join('\n');
  await page.evaluate(([name, text]) => { window.gsvEditor.show(name); window.gsvEditor.files().find((f) => f.name === name).doc.setValue(text); }, [file, broken]);
  // Not rebuilt while the student may still be typing; Ctrl+Enter rebuilds at once.
  const whileTyping = await page.evaluate(() => document.getElementById('shader-error').textContent);
  await page.click('#code .CodeMirror');
  await page.keyboard.press('Control+Enter');
  const onShortcut = await page.evaluate(() => document.getElementById('shader-error').textContent);
  check(whileTyping === '' && onShortcut !== '', lab + ' editor: an edit is not rebuilt mid-typing, and Ctrl+Enter rebuilds it at once' +
        (whileTyping !== '' ? ' (it was rebuilt at once)' : onShortcut === '' ? ' (Ctrl+Enter did not rebuild)' : ''));
  await page.waitForFunction(() => document.getElementById('shader-error').textContent !== '', null, { timeout: 10000 });
  const shown = await page.evaluate(() => document.getElementById('shader-error').textContent);
  const expectedLine = at + 2;
  const where = /([\w./-]+):(\d+)/.exec(shown);
  check(where && where[1].endsWith(file) && Number(where[2]) === expectedLine,
        lab + ' a broken edit shows the student\'s file:line: ' + shown.split('\n')[0].slice(0, 140) + ' (expected ' + file + ':' + expectedLine + ')');
  await page.waitForTimeout(200);
  check((await canvasPixels(page)).url === before, lab + ' the broken edit keeps the last picture');
  await page.screenshot({ path: path.join(out, lab + '-broken-edit.png'), fullPage: true });
  // Fixed by hand after lines were typed above it: the error's mark goes with the error, on no line.
  const stale = await page.evaluate((name) => {
    const f = window.gsvEditor.files().find((g) => g.name === name);
    f.doc.replaceRange('// a note\n// another\n', { line: 0, ch: 0 });
    const bad = f.doc.getValue().split('\n').findIndex((l) => /this is not GLSL/.test(l));
    f.doc.replaceRange('    // was not GLSL', { line: bad, ch: 0 }, { line: bad, ch: f.doc.getLine(bad).length });
    window.gsvEditor.rebuildNow();
    const marked = [];
    for (let i = 0; i < f.doc.lineCount(); ++i) if (/error-line/.test(f.doc.lineInfo(i).bgClass || '')) marked.push(i + 1);
    return { error: document.getElementById('shader-error').textContent, marked };
  }, file);
  check(stale.error === '' && stale.marked.length === 0, lab + ' editor: fixed, no line stays marked' +
        (stale.marked.length ? ' (lines ' + stale.marked.join(', ') + ' still marked)' : '') + (stale.error ? ' (error: ' + stale.error.slice(0, 80) + ')' : ''));
  // The fix: a comment added, so the edit differs from the reference and is kept.
  const fixed = original.replace(/void main\(\) \{/, 'void main() { // edited in the page');
  await page.evaluate(([name, text]) => window.gsvEditor.files().find((f) => f.name === name).doc.setValue(text), [file, fixed]);
  await page.waitForFunction(() => document.getElementById('shader-error').textContent === '', null, { timeout: 10000 });
  await page.waitForTimeout(200);
  check((await canvasPixels(page)).url === before, lab + ' fixing it restores the picture');
  await page.reload();
  await page.waitForFunction(() => window.gsvPage && window.gsvPage.frames > 0, null, { timeout: 60000 });
  const kept = await page.evaluate((name) => window.gsvEditor.files().find((f) => f.name === name).doc.getValue(), file);
  check(kept === fixed, lab + ' a reload keeps the edit');
  const download = page.waitForEvent('download');
  await page.click('#download');
  const zip = path.join(out, lab + '-download.zip');
  await (await download).saveAs(zip);
  const submission = path.join(out, lab + '-submission');
  fs.rmSync(submission, { recursive: true, force: true });
  fs.mkdirSync(submission, { recursive: true });
  execFileSync('python3', ['-m', 'zipfile', '-e', zip, submission]);
  const folder = fs.readdirSync(path.join(submission, 'labs'))[0];
  const graded = fs.readFileSync(path.join(submission, 'labs', folder, file), 'utf8');
  check(graded === fixed, lab + ' the download holds labs/' + folder + '/' + file + ' as edited');
  const table = gradeNatively(['--submission', submission, '--labs', lab], lab + '-download');
  const total = /total\s+([\d.]+)\s*\/\s*([\d.]+)/.exec(table);
  check(total && total[1] === total[2], lab + ' gsv-grade --submission grades the downloaded files: ' + (total ? total[0] : table.slice(-300)));
  await page.evaluate(() => localStorage.clear());
  await page.close();
}

// Each fault gives one clear line in the page, and nothing is lost.
async function faults(context, browser) {
  const status = (page) => page.evaluate(() => document.getElementById('status').textContent);
  // Opened from file://: the page says to serve it.
  const fromFile = await context.newPage();
  await fromFile.goto('file://' + path.resolve(args.site, 'site/lab01/index.html'));
  await fromFile.waitForTimeout(300);
  const fileLine = await status(fromFile);
  check(/file:\/\//.test(fileLine) && /http/.test(fileLine), 'file:// says: ' + fileLine);
  await fromFile.close();
  // A browser without WebGL 2: named.
  const noGl = await context.newPage();
  await noGl.addInitScript(() => {
    const get = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function (kind, ...rest) { return kind === 'webgl2' ? null : get.call(this, kind, ...rest); };
  });
  await noGl.goto(args.base + '/site/lab01/index.html');
  await noGl.waitForTimeout(300);
  const glLine = await status(noGl);
  check(/no WebGL 2/.test(glLine), 'no WebGL 2 says: ' + glLine);
  await noGl.close();
  // A shared package missing from the site (its data, then its loader): the page names the package and the file.
  for (const file of ['meshes.data', 'meshes.js']) {
    const missing = await context.newPage();
    await missing.route('**/site/shared/' + file, (route) => route.fulfill({ status: 404, body: 'Not Found' }));
    await missing.goto(args.base + '/site/lab01/index.html');
    await missing.waitForFunction(() => window.gsvPage && (window.gsvPage.frames > 0 || window.gsvPage.failed), null, { timeout: 60000 })
      .catch(() => {});
    const missingLine = await status(missing);
    check(/data package meshes/.test(missingLine) && missingLine.includes('/site/shared/' + file),
          'without shared/' + file + ' lab01 says: ' + missingLine);
    await missing.close();
  }
  // A missing extension a lab needs: the ES refusal's words.
  // Lab 02 starts, and its frame is refused with the ES refusal's line (the page's status; no frame is drawn).
  const noLinear = await context.newPage();
  await noLinear.goto(args.base + '/site/lab02/index.html?without=OES_texture_float_linear');
  await noLinear.waitForFunction(() => window.gsvPage && (window.gsvPage.frames > 0 || window.gsvPage.failed ||
                                 (window.gsvPage.ready && document.getElementById('status').className === 'warning')),
                                 null, { timeout: 120000 });
  const linearLine = await status(noLinear);
  check(/GL_OES_texture_float_linear/.test(linearLine), 'without OES_texture_float_linear lab02 says: ' + linearLine);
  await noLinear.screenshot({ path: path.join(out, 'lab02-without-float-linear.png'), fullPage: true });
  await noLinear.close();
  const { page: noFloat } = await openPage(context, args.base + '/site/lab01/index.html?without=EXT_color_buffer_float');
  await noFloat.evaluate(() => window.gsvSelfCheck.run('diffuse'));
  const floatLine = await noFloat.evaluate(() => document.getElementById('driver-note').textContent);
  check(/GL_EXT_color_buffer_float/.test(floatLine), 'without EXT_color_buffer_float lab01 says: ' + floatLine);
  await noFloat.close();
  // A file that is not one of the lab's, and storage that refuses the edits.
  const stranger = path.join(out, 'notes.txt');
  fs.writeFileSync(stranger, 'not a shader');
  const refusing = await context.newPage();
  await refusing.addInitScript(() => {
    Storage.prototype.setItem = function () { throw new DOMException('the quota is used up', 'QuotaExceededError'); };
  });
  await refusing.goto(args.base + '/site/lab01/index.html');
  await refusing.waitForFunction(() => window.gsvPage && window.gsvPage.frames > 0);
  await refusing.setInputFiles('#open', [stranger]);
  await refusing.waitForFunction(() => /^Not opened/.test(document.getElementById('status').textContent));
  const openLine = await status(refusing);
  check(/notes\.txt/.test(openLine) && /nothing else was changed/.test(openLine), 'a file not of the lab says: ' + openLine);
  await refusing.evaluate(() => { const f = window.gsvEditor.files()[0]; f.doc.setValue(f.doc.getValue() + '\n// kept'); });
  await refusing.waitForFunction(() => document.getElementById('storage-note').textContent !== '', null, { timeout: 5000 });
  const storageLine = await refusing.evaluate(() => document.getElementById('storage-note').textContent);
  const kept = await refusing.evaluate(() => window.gsvEditor.files()[0].doc.getValue().endsWith('// kept'));
  check(/only copy/.test(storageLine) && kept, 'storage refused says: ' + storageLine + (kept ? ' (the edit stays in the editor)' : ' (the edit is LOST)'));
  // A lost context: one line, edits kept.
  await refusing.evaluate(() => {
    window.gsvTestLoseContext = document.getElementById('canvas').getContext('webgl2').getExtension('WEBGL_lose_context');
    window.gsvTestLoseContext.loseContext();
  });
  await refusing.waitForTimeout(300);
  const lostLine = await status(refusing);
  const stillThere = await refusing.evaluate(() => window.gsvEditor.files()[0].doc.getValue().endsWith('// kept'));
  check(/WebGL context/.test(lostLine) && stillThere, 'a lost context says: ' + lostLine);
  // Given back: the lab's GPU objects went with the old context, so the line says to reload; the edit is still there.
  await refusing.evaluate(() => window.gsvTestLoseContext.restoreContext());
  await refusing.waitForFunction(() => /came back/.test(document.getElementById('status').textContent), null, { timeout: 10000 });
  const backLine = await status(refusing);
  const keptAfter = await refusing.evaluate(() => window.gsvEditor.files()[0].doc.getValue().endsWith('// kept'));
  check(/reload/.test(backLine) && keptAfter, 'a restored context says: ' + backLine);
  await refusing.screenshot({ path: path.join(out, 'lab01-context-lost.png'), fullPage: true });
  await refusing.close();
}

// A deck beside its live lab (the decks are there where the slides test or scripts/kit slides built them): on the
// students' site the starter, on the lecturer's the solution, which draws a picture, not the starter's flat colour.
async function deckWithLiveLab(context, site) {
  const deck = path.resolve(args.site, site + '/slides/01-gooch.html');
  if (/not built yet/.test(fs.readFileSync(deck, 'utf8').slice(0, 2000))) {
    console.log('     ' + args.rasterizer + ': deck 01 not built (the slides test, or scripts/kit slides, builds it): the deck screenshot is skipped');
    return;
  }
  const page = await context.newPage();
  await page.setViewportSize(site === 'lecturer' ? { width: 1920, height: 1080 } : { width: 1024, height: 768 });
  await page.goto(args.base + '/' + site + '/slides/01-gooch.html');
  const last = await page.evaluate(() => document.querySelectorAll('body > section').length);
  await page.goto(args.base + '/' + site + '/slides/01-gooch.html#' + last);
  await page.waitForTimeout(1500);  // dzslides' transition
  const frame = page.frames().find((f) => /lab01\/index\.html/.test(f.url()));
  if (frame) await frame.waitForFunction(() => window.gsvPage && (window.gsvPage.frames > 0 || window.gsvPage.failed), null, { timeout: 60000 });
  check(!!frame && frame.url().includes('/' + site + '/'), 'the lab 01 deck\'s last slide on ' + site + '/ holds its live lab' + (frame ? ' (' + frame.url().replace(args.base, '') + ')' : ''));
  if (frame && site === 'lecturer') {
    const pixels = await canvasPixels(frame);
    check(!pixels.flat, 'the lecturer\'s deck runs the solution: a picture, not one flat colour');
  }
  if (frame) {
    // The slide's page is embedded: the picture, larger than the lab's size, and its parameters, no editor.
    const shown = await frame.evaluate(() => ({ editor: getComputedStyle(document.getElementById('editor')).display,
      panel: getComputedStyle(document.getElementById('panel')).display, width: document.getElementById('canvas').width,
      own: window.gsvPage.description.width }));
    check(/[?&]embed/.test(frame.url()) && shown.editor === 'none' && shown.panel !== 'none' && shown.width > shown.own,
          'the slide on ' + site + '/ embeds the picture (' + shown.width + ' px wide, the lab\'s ' + shown.own + ') and its parameters, no editor');
  }
  await page.waitForTimeout(500);
  await page.screenshot({ path: path.join(out, 'deck-01-live-lab-' + site + '.png') });
  await page.close();
}

// The lecturer's site: every page says it holds the answers (the students' pages do not); a picture goes full screen
// at the screen's size and comes back at the lab's.
async function lecturerSite(context) {
  const student = await context.newPage();
  await student.goto(args.base + '/site/lab01/index.html');
  const studentNote = await student.evaluate(() => document.querySelectorAll('.lecturer-note').length);
  await student.close();
  const { page, problems } = await openPage(context, args.base + '/lecturer/lab01/index.html');
  await page.setViewportSize({ width: 1920, height: 1080 });
  const note = await page.evaluate(() => (document.querySelector('.lecturer-note') || {}).textContent || '');
  check(/Never publish/.test(note) && studentNote === 0, 'the lecturer\'s pages say they hold the answers, the students\' do not: ' + note);
  const own = await page.evaluate(() => [window.gsvPage.description.width, window.gsvPage.description.height]);
  await page.click('#fullscreen-button');
  await page.waitForFunction(() => /^full screen/.test(document.getElementById('status').textContent), null, { timeout: 10000 })
    .catch(() => {});
  await page.waitForTimeout(500);
  const full = await page.evaluate(() => ({ width: document.getElementById('canvas').width, height: document.getElementById('canvas').height,
    screen: [Math.round(window.innerWidth * devicePixelRatio), Math.round(window.innerHeight * devicePixelRatio)],
    status: document.getElementById('status').textContent }));
  await page.screenshot({ path: path.join(out, 'lecturer-lab01-full-screen.png') });
  const pixels = await canvasPixels(page);
  check(full.width === full.screen[0] && full.height === full.screen[1] && !pixels.flat,
        'full screen: the solution drawn at ' + full.width + 'x' + full.height + ' for a ' + full.screen.join('x') + ' screen (' + full.status + ')');
  await page.evaluate(() => document.exitFullscreen());
  await page.waitForTimeout(500);
  const back = await page.evaluate(() => [document.getElementById('canvas').width, document.getElementById('canvas').height]);
  check(back.join() === own.join(), 'leaving full screen: the picture at the lab\'s ' + own.join('x') + ' again (' + back.join('x') + ')');
  check(problems.length === 0, 'lecturer\'s page: no console error' + (problems.length ? ': ' + problems.join('; ') : ''));
  await page.close();
}

// Every link and every image, script and style on the site's pages answers (the index, each lab's page, the decks'
// index and each deck's page or its "not built yet" page), followed from the index; a deck's own images are inline.
async function linksAnswer(site) {
  const seen = new Set();
  const queue = [args.base + '/' + site + '/index.html'];
  const broken = [];
  while (queue.length) {
    const url = queue.shift();
    if (seen.has(url)) continue;
    seen.add(url);
    const reply = await fetch(url);
    if (!reply.ok) { broken.push(url.replace(args.base, '') + ' (' + reply.status + ')'); continue; }
    if (!/\.html$/.test(new URL(url).pathname)) continue;
    const html = await reply.text();
    for (const m of html.matchAll(/(?:href|src)="([^"#]+)(?:#[^"]*)?"/g)) {
      if (/^(data:|mailto:|javascript:)/.test(m[1])) continue;
      const next = new URL(m[1], url);
      if (next.origin === new URL(args.base).origin && next.pathname.startsWith('/' + site + '/')) queue.push(next.href);
    }
  }
  check(broken.length === 0, 'every link on ' + site + '/ answers (' + seen.size + ' followed)' + (broken.length ? ': ' + broken.join(', ') : ''));
}

(async () => {
  if (args.editor) {
    await linksAnswer('site');
    await linksAnswer('lecturer');
  }
  const browser = await chromium.launch({
    executablePath: process.env.GSV_CHROMIUM || '/usr/bin/chromium', headless: true,
    args: ['--no-sandbox', ...rasterizers[args.rasterizer]],
  });
  const context = await browser.newContext({ acceptDownloads: true, viewport: { width: 1280, height: 900 } });
  const probe = await context.newPage();
  await probe.goto(args.base + '/site/index.html');
  const renderer = await probe.evaluate(() => {
    const gl = document.createElement('canvas').getContext('webgl2');
    const info = gl && gl.getExtension('WEBGL_debug_renderer_info');
    return gl ? (info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER)) : 'no WebGL 2';
  });
  console.log('     ' + args.rasterizer + ': WebGL 2 on ' + renderer);
  await probe.screenshot({ path: path.join(out, 'index.png'), fullPage: true });
  await probe.close();
  for (const lab of labs) {
    const t0 = Date.now();
    try {
      await starterPage(context, lab);
      await solutionPage(context, lab);
    } catch (e) {
      check(false, lab + ': ' + e.message.split('\n')[0]);
    }
    console.log('     ' + args.rasterizer + ' ' + lab + ': its pages took ' + ((Date.now() - t0) / 1000).toFixed(0) + ' s');
  }
  if (args.editor) {
    const t0 = Date.now();
    try {
      await studentsPage(context, 'lab01');
      await particleLimit(context);
      await oneTodoUndone(context, 'lab01', 'L01-T4');
      await knownMistake(context, 'lab01', 'the normal left in the model\'s space');
      for (const lab of labs) await oneTodoAtATime(context, lab);
      await editor(context, 'lab01');
      await faults(context, browser);
      await deckWithLiveLab(context, 'site');
      await deckWithLiveLab(context, 'lecturer');
      await lecturerSite(context);
    } catch (e) {
      check(false, 'editor: ' + e.message.split('\n')[0]);
    }
    console.log('     ' + args.rasterizer + ': one TODO undone, the editor, the faults and the deck took ' + ((Date.now() - t0) / 1000).toFixed(0) + ' s');
  }
  await browser.close();
  console.log(args.rasterizer + ': ' + (checks - failures) + ' passed, ' + failures + ' failed');
  process.exit(failures ? 1 : 0);
})();
