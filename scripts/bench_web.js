#!/usr/bin/env node
// The browser edition's speed (scripts/kit bench): per lab, the page's weight (its .js, .wasm and .data, and the shared
// data packages it reads: its folders of data/ and the font), the time from navigation to the first frame of the page
// a student opens (the starter's), and the reference solution's frame time in the page against the native binary's on the same machine and rasterizer
// (llvmpipe: through ANGLE in the page, through EGL natively), the lab's first case at its case size, in interleaved
// rounds: the ratio's median and its lowest and highest round. Both do the same work a frame: render mode's frames
// (lab 05 runs its steps from the start in each), into the float target where there is one. The page's frames are
// timed as a batch between two waits for the GPU (Module.timeFrames), since the page's wait is a read-back with a
// fixed cost of about 2 ms; native frames are timed one by one with glFinish, their median.
// Usage: bench_web.js SITE_URL BUILD_WEB_DIR BIN_DIR KIT_ROOT   (run under X: ANGLE's GL back end needs a display)
'use strict';
const fs = require('fs');
const path = require('path');
const { execFileSync } = require('child_process');
const { chromium } = require(path.join(__dirname, '../web/node_modules/playwright-core'));

const [base, buildWeb, bin, kit] = process.argv.slice(2);
// Every lab of the kit's list (scripts/kit_labs.py); GSV_BENCH_LABS=lab05,lab07 times only those.
const labs = process.env.GSV_BENCH_LABS ? process.env.GSV_BENCH_LABS.split(',')
  : execFileSync('python3', [path.join(kit, 'scripts', 'kit_labs.py'), '--kit', kit, '--ids'], { encoding: 'utf8' }).trim().split(',');
const rounds = 3, frames = 10;
const median = (v) => { const s = [...v].sort((a, b) => a - b); return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2; };
const kib = (bytes) => (bytes / 1024).toFixed(0);

function nativeMs(lab, caseName, size) {
  const out = fs.mkdtempSync('/tmp/gsv-bench-web-');
  execFileSync(path.join(bin, lab + '_solution'), ['render', '--case', caseName, '--size', size, '--profile', 'es',
    '--frames', String(frames), '--warmup', '1', '--out', path.join(out, 'frame.png')], { stdio: 'ignore' });
  const report = JSON.parse(fs.readFileSync(path.join(out, 'frame.json'), 'utf8'));
  fs.rmSync(out, { recursive: true, force: true });
  return report.timing.median_ms;
}

(async () => {
  const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', headless: true,
    args: ['--no-sandbox', '--use-gl=angle', '--use-angle=gl', '--ignore-gpu-blocklist'] });
  // Each shared package is fetched once, by the first page that reads it (the page's data-packages, cmake/web.cmake).
  const packageKib = (name) => kib(fs.statSync(path.join(buildWeb, 'site', 'shared', name + '.data')).size);
  console.log('lab    weight KiB (js+wasm+data)  starter first frame ms  page ms/frame  native ms/frame  ' +
              'page/native (lowest, highest round)  shared packages KiB');
  for (const lab of labs) {
    const dir = path.join(buildWeb, 'site', lab);
    const weight = ['js', 'wasm', 'data'].map((e) => fs.statSync(path.join(dir, lab + '.' + e)).size);
    const html = fs.readFileSync(path.join(dir, 'index.html'), 'utf8');
    const packages = ((html.match(/data-packages="([^"]*)"/) || [])[1] || '').split(' ').filter((n) => n);
    const cases = JSON.parse(fs.readFileSync(path.join(kit, 'grader/cases', lab + '.json'), 'utf8'));
    const caseName = cases.cases[0].name, size = cases.size;
    // The first frame a student sees: the starter's page, in a fresh context (nothing cached).
    const fresh = await browser.newContext();
    const starter = await fresh.newPage();
    await starter.goto(base + '/site/' + lab + '/index.html');
    await starter.waitForFunction(() => window.gsvPage && (window.gsvPage.frames > 0 || window.gsvPage.failed), null, { timeout: 120000 });
    const first = await starter.evaluate(() => window.gsvPage.firstFrameMs);
    await fresh.close();
    const page = await browser.newPage();
    await page.goto(base + '/lecturer/' + lab + '/index.html?case=' + caseName);
    await page.waitForFunction(() => window.gsvPage && (window.gsvPage.frames > 0 || window.gsvPage.failed), null, { timeout: 120000 });
    const ratios = [], pageTimes = [], nativeTimes = [];
    for (let r = 0; r < rounds; r++) {
      const inPage = await page.evaluate((n) => {
        Module.applyCase(new URLSearchParams(location.search).get('case'));
        return Module.timeFrames(n);
      }, frames);
      if (inPage < 0) throw new Error(lab + ': the page could not time its frames: ' + await page.evaluate(() => Module.status()));
      const native = nativeMs(lab, caseName, size);
      pageTimes.push(inPage);
      nativeTimes.push(native);
      ratios.push(inPage / native);
    }
    // A change as a student makes it, where the lab spreads its work over frames (lab 05's steps): from the change to
    // the frame that is at its time, and the longest frame on the way (the page's freeze, if any). At the case timed
    // above, and where the page opens on a smaller case than the lab's defaults ("page_case": lab 05's 65,536
    // particles, not its million), at the defaults too: the change to them, then a seed changed there.
    const timeChange = (change) => page.evaluate((change) => new Promise((resolve) => {
      const description = window.gsvPage.description;
      const seed = description.params.find((p) => p.name === 'seed');
      if (!seed || !description.params.find((p) => p.animated)) return resolve(null);
      const t0 = performance.now(), frames0 = window.gsvPage.frames;
      let last = t0, longest = 0;
      if (change === 'defaults') window.gsvPage.changed(Module.applyCase(''));
      else window.gsvPage.changed(Module.setParam('seed', String(Number(JSON.parse(Module.states()).find((s) => s.name === 'seed').value) + 1)));
      const watch = () => {
        const now = performance.now();
        longest = Math.max(longest, now - last);
        last = now;
        if (window.gsvPage.frames > frames0 && !window.gsvPage.dirty && !Module.drawAgain())
          return resolve({ ms: now - t0, frames: window.gsvPage.frames - frames0, longest });
        requestAnimationFrame(watch);
      };
      requestAnimationFrame(watch);
    }), change);
    const sayChange = (what, change) => {
      if (change) console.log('       ' + lab + ': ' + what + ' to the picture at its time: ' + change.ms.toFixed(0) + ' ms over ' +
                              change.frames + ' frames, the longest gap between frames ' + change.longest.toFixed(0) + ' ms');
    };
    sayChange('a change (seed) at case ' + caseName, await timeChange('seed'));
    if (cases.page_case) {
      sayChange('the lab\'s defaults applied', await timeChange('defaults'));
      sayChange('a change (seed) at the defaults', await timeChange('seed'));
    }
    await page.close();
    console.log(lab.padEnd(6) + ' ' + (kib(weight[0]) + '+' + kib(weight[1]) + '+' + kib(weight[2])).padEnd(26) +
                String(Math.round(first)).padStart(22) + median(pageTimes).toFixed(1).padStart(15) +
                median(nativeTimes).toFixed(1).padStart(17) + '   ' + median(ratios).toFixed(2) + ' (' +
                Math.min(...ratios).toFixed(2) + ', ' + Math.max(...ratios).toFixed(2) + ')   ' +
                (packages.map((n) => n + ' ' + packageKib(n)).join(', ') || 'none'));
  }
  await browser.close();
})();
