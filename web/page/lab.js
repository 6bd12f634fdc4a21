// A lab's page: starts the lab's WebAssembly in web mode (common/app/app_web.cpp), builds the controls from the lab's
// own declarations, draws when something changed, and hands the student's shader edits to the lab's shader library.
// Everything the page says goes on one status line; the tests read window.gsvPage.
'use strict';
(function () {
  const $ = (id) => document.getElementById(id);
  const lab = document.body.dataset.lab;
  const query = new URLSearchParams(location.search);
  const page = window.gsvPage = {
    lab, ready: false, failed: '', frames: 0, lastFrameMs: NaN, description: null, errors: [], log: [],
    dirty: true, playing: false, caseIndex: -1, view: 'yours',
  };

  function say(line, kind) {
    const status = $('status');
    status.textContent = line;
    status.className = kind || '';
    if (kind === 'error') page.failed = line;
  }
  function log(line) {
    page.log.push(line);
    $('log').textContent += line + '\n';
  }
  page.say = say;

  // Faults that stop the page before anything is loaded, each in one line.
  if (location.protocol === 'file:') {
    say('This page was opened from file://, where a browser will not load its WebAssembly and data: serve the folder ' +
        '(scripts/kit serve, or any static web server) and open it through http://.', 'error');
    return;
  }
  const probe = document.createElement('canvas');
  if (!probe.getContext('webgl2')) {
    const webgl1 = !!probe.getContext('webgl');
    say('This browser gives the page no WebGL 2 context' + (webgl1 ? ' (it has WebGL 1 only)' : ' (nor WebGL 1)') +
        ': the labs need WebGL 2, which is OpenGL ES 3.0. A current Chrome, Edge, Firefox or Safari has it; ' +
        'check that hardware acceleration is on.', 'error');
    return;
  }

  // An extension hidden from the lab, to see the page without it (and to test that): ?without=OES_texture_float_linear.
  for (const name of query.getAll('without')) {
    const proto = WebGL2RenderingContext.prototype;
    const supported = proto.getSupportedExtensions, get = proto.getExtension;
    proto.getSupportedExtensions = function () { return (supported.call(this) || []).filter((e) => e !== name); };
    proto.getExtension = function (e) { return e === name ? null : get.call(this, e); };
  }

  // The packages the lab reads besides its own (cmake/web.cmake: the folders of data/ it opens, and the font), each at
  // ../shared/ where every page that reads it finds it, so the browser fetches it once across the labs' pages.
  const packages = (document.body.dataset.packages || '').split(' ').filter((name) => name);
  const sharedFiles = new Set(packages.map((name) => name + '.data'));

  window.Module = {
    canvas: $('canvas'),
    noInitialRun: true,
    print: (line) => log(line),
    // The lab's stderr is its messages (the GL it got, a refusal, a note such as "frames render into RGBA8"): the
    // page's log, and once it runs its status line, not console errors.
    printErr: (line) => {
      log(line);
      if (!page.ready || !line.startsWith(lab + ':')) return;
      say(line, 'warning');
      // What the browser's driver lacks (an extension, so a fallback) stays in view after the status line moves on.
      if (/ lacks GL_| needs GL_/.test(line)) {
        const note = $('driver-note');
        if (!note.textContent.includes(line)) note.textContent += (note.textContent ? '\n' : '') + line;
        note.hidden = false;
      }
    },
    // The page's other scripts (the editor, the self-check) come after this one: the lab starts once they have run.
    onRuntimeInitialized: () => {
      if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', () => start());
      else start();
    },
    locateFile: (file, prefix) => (sharedFiles.has(file) ? '../shared/' + file : prefix + file),
    onAbort: (what) => say('The lab stopped: ' + what + ' (reload the page; your edits are kept).', 'error'),
  };
  // Each package's loader starts its fetch and queues its files for the lab's start, so every one of them runs before
  // the lab's own script, whose WebAssembly starts the lab once the files it waits for are in.
  const load = (src, what, next) => {
    const script = document.createElement('script');
    script.src = src;
    script.onload = next;
    script.onerror = () => say('Could not load ' + what + ' (' + script.src + '): is the page served from its built folder?',
                               'error');
    document.body.appendChild(script);
  };
  // A package's .data that does not come (not found, a network error) is thrown by Emscripten's loader from its
  // request's callback, which the page cannot wrap; the lab would wait for it for ever. The message names the file.
  window.addEventListener('error', (event) => {
    const message = String(event.message || '');
    const name = [...packages, lab].find((n) => new RegExp('(^|[/ ])' + n + '\\.data$').test(message));
    if (!name || page.ready) return;
    const file = new URL(Module.locateFile(name + '.data', ''), location.href).href;
    const reason = /NetworkError/.test(message) ? 'a network error' : (message.match(/Error: (.+?) : /) || [])[1] || 'refused';
    say(name === lab
      ? 'Could not load the lab\'s own files, ' + file + ' (' + reason + '): is the page served from its built folder?'
      : 'Could not load the data package ' + name + ', ' + file + ' (' + reason + '): ' + lab + ' cannot start without it; ' +
        'is the site\'s shared/ folder complete?', 'error');
  });
  let loaders = packages.length;
  const loadLab = () => load(lab + '.js', 'the lab', null);
  if (!loaders) loadLab();
  for (const name of packages) {
    load('../shared/' + name + '.js', 'the loader of the data package ' + name, () => { if (--loaders === 0) loadLab(); });
  }

  // The lab's case file: its "size", so the picture is the one its cases and golden images have, and its "page_case",
  // the case the page opens on where the address names none (lab 05's 65,536 particles: its default million take
  // about 6 s to a first frame in a page on a CPU rasterizer).
  function caseFile(root) {
    try {
      return JSON.parse(Module.FS.readFile(root + '/grader/cases/' + lab + '.json', { encoding: 'utf8' }));
    } catch (e) {
      return {};
    }
  }

  function run(args) {
    try {
      Module.callMain(args);
    } catch (e) {
      if (!(e && e.name === 'ExitStatus')) log(String(e) + (e && e.stack ? '\n' + e.stack : ''));
    }
    try {
      return JSON.parse(Module.describe());
    } catch (e) {
      return null;
    }
  }

  function start() {
    page.runtimeMs = performance.now();  // the WebAssembly and every package in (since navigation began)
    const root = '/kit';
    const cases = caseFile(root);
    const args = ['web', '--size', query.get('size') || cases.size || '512x512'];
    const opening = query.get('case') || cases.page_case;
    if (opening) args.push('--case', opening);
    const before = page.log.length;
    const editor = window.gsvEditor;
    // The student's edits go in before the lab starts; a lab cannot start with a broken shader, so where they do not
    // build, it starts from the starter and the edits are then reloaded (the error shown, the starter's picture kept).
    const restored = editor ? editor.restoreIntoFiles(root, lab) : 0;
    let description = run(args);
    if (!description && restored && editor) {
      editor.writeStarterFiles();
      description = run(args);
      if (description) editor.writeEditedFiles();
    }
    if (!description) {
      const lines = page.log.slice(before).filter((l) => l.startsWith(lab + ':') && !/ backend$/.test(l));
      say(lines.length ? lines[lines.length - 1] : 'The lab did not start (see its output below).', 'error');
      return;
    }
    page.description = description;
    const canvas = $('canvas');
    canvas.style.width = description.width + 'px';
    canvas.style.height = description.height + 'px';
    if (embedded) fitToView();
    buildControls(description.params);
    buildCases(description.cases, opening);
    bindKeysAndMouse();
    watchContext(canvas);
    page.ready = true;
    page.startedMs = performance.now();  // the lab started: its shaders built, its controls made
    say(description.title + ' (' + description.variant + ') on ' + description.gl);
    if (editor) editor.open(description, () => { page.dirty = true; });
    if (window.gsvSelfCheck) window.gsvSelfCheck.attach(description);
    requestAnimationFrame(loop);
  }

  // Drawn only when something changed (or while playing): an idle page costs nothing.
  let lastTime = 0;
  function loop(time) {
    if (page.lost) return;
    if (page.checking) {  // the self-check draws its cases between frames (self_check.js): the page waits for it
      lastTime = 0;
      requestAnimationFrame(loop);
      return;
    }
    if (page.playing) {
      const error = Module.play(lastTime ? (time - lastTime) / 1000 : 0);
      if (error) say(error, 'warning');
      page.dirty = true;
      refreshStates();
    }
    lastTime = time;
    if (page.dirty) {
      page.dirty = false;
      const ms = Module.draw();
      if (ms >= 0) {
        if (Module.drawAgain()) page.dirty = true;  // the lab's picture is behind its values (lab 05's steps)
        page.frames++;
        if (page.frames === 1) page.firstFrameMs = performance.now();  // since navigation began
        page.lastFrameMs = ms;
        const progress = Module.progress();  // the lab's work spread over frames (lab 05's steps), while behind
        $('frame-time').textContent = 'frame ' + ms.toFixed(1) + ' ms, ' + frameTimeNote() + (progress ? '; ' + progress : '');
      } else {
        say(Module.status(), 'warning');
        refreshStates();
      }
    }
    requestAnimationFrame(loop);
  }

  // glFinish brackets the frame natively; in the page, WebGL's finish() returns early, so a frame is bracketed by a
  // one-pixel read-back, which waits for the browser's GPU process to run every command before it. Only one frame in
  // each half second is timed so: the wait stalls the GPU process, and paid by every frame it halved a drag's speed.
  function frameTimeNote() {
    return 'one frame each half second timed between two one-pixel read-backs, which wait for the GPU';
  }

  function changed(error) {
    if (error) say(error, 'warning');
    else if ($('status').className === 'warning') say(page.description.title + ' on ' + page.description.gl);
    page.dirty = true;
    refreshStates();
  }
  page.changed = changed;

  // ---- Controls from the lab's declarations (common/app/page_description.cpp) ----
  const controls = new Map();

  function buildControls(params) {
    const form = $('controls');
    form.textContent = '';
    for (const p of params) {
      const row = document.createElement('div');
      row.className = 'param';
      const label = document.createElement('label');
      label.textContent = p.name;
      label.title = p.help;
      const input = makeInput(p);
      input.id = 'param-' + p.name;
      input.name = p.name;
      label.htmlFor = input.id;
      const value = document.createElement('output');
      const note = document.createElement('small');
      note.className = 'why';
      row.append(label, input, value, note);
      const help = document.createElement('small');
      help.className = 'help';
      help.textContent = p.help + (p.compile_time ? ' (compiled in)' : '') + (p.knob ? ' (the accuracy knob)' : '') +
          (p.same_picture ? '. May draw the same picture: ' + p.same_picture : '');
      row.append(help);
      form.append(row);
      controls.set(p.name, { spec: p, row, input, value, note });
      input.addEventListener(p.kind === 'float' || p.kind === 'int' ? 'input' : 'change', () => {
        const value = readInput(p, input);
        const error = Module.setParam(p.name, value);
        changed(error);
        // A change that may leave the picture as it was says why at once, so it is not taken for a change that failed.
        if (!error && p.same_picture) say(p.name + '=' + value + ' may draw the same picture: ' + p.same_picture);
      });
    }
    refreshStates();
  }

  function makeInput(p) {
    if (p.kind === 'choice') {
      const select = document.createElement('select');
      for (const c of p.choices) select.append(new Option(c, c));
      return select;
    }
    const input = document.createElement('input');
    if (p.kind === 'bool') input.type = 'checkbox';
    else if (logScale(p)) {
      input.type = 'range';  // the slider's position, 0 to kLogSteps; the value is min * (max / min)^(position / kLogSteps)
      input.min = 0;
      input.max = kLogSteps;
      input.step = 1;
    } else if (p.kind === 'float' || p.kind === 'int') {
      input.type = 'range';
      input.min = p.min;
      input.max = p.max;
      input.step = p.kind === 'int' ? 1 : 'any';
    } else input.type = 'text';  // vec3 as "x,y,z", a file by its path
    return input;
  }

  // A whole number over several orders of magnitude (lab 05's 1 to 16,777,216 particles: 131,072 a pixel on a linear
  // slider) moves in equal ratios, not equal steps.
  const kLogSteps = 1000;
  function logScale(p) { return p.kind === 'int' && p.min >= 1 && p.max / p.min >= 1000; }
  function fromPosition(p, position) { return Math.round(p.min * Math.pow(p.max / p.min, position / kLogSteps)); }
  function toPosition(p, value) { return Math.round(kLogSteps * Math.log(value / p.min) / Math.log(p.max / p.min)); }

  function readInput(p, input) {
    if (p.kind === 'bool') return input.checked ? 'on' : 'off';
    if (logScale(p)) return String(fromPosition(p, Number(input.value)));
    return input.value;
  }

  function refreshStates() {
    for (const s of JSON.parse(Module.states())) {
      const c = controls.get(s.name);
      if (!c) continue;
      if (c.spec.kind === 'bool') c.input.checked = s.value === 'on';
      else if (document.activeElement !== c.input || c.spec.kind === 'choice')
        c.input.value = logScale(c.spec) ? toPosition(c.spec, Number(s.value)) : s.value;
      c.value.textContent = c.spec.kind === 'bool' ? '' : s.value;
      // Greyed with the window's reason: what would enable it.
      c.input.disabled = !!s.inactive;
      c.row.classList.toggle('inactive', !!s.inactive);
      c.note.textContent = s.inactive ? 'no effect now: it ' + s.inactive : '';
      c.row.title = s.inactive ? 'no effect now: it ' + s.inactive : '';
    }
  }

  // ---- Named cases ----
  function buildCases(cases, opening) {
    const select = $('case');
    for (const c of cases) select.append(new Option(c.name + (c.todo ? ' (' + c.todo + ')' : ' (demo)'), c.name));
    select.addEventListener('change', () => pickCase(select.selectedIndex - 1));
    if (opening) {
      select.value = opening;
      page.caseIndex = cases.findIndex((c) => c.name === opening);
    }
    describeCase();
  }

  function describeCase() {
    const c = page.description.cases[$('case').selectedIndex - 1];
    $('case-description').textContent = c ? c.description + (c.settings.length ? ' — ' + c.settings.join(' ') : '') : '';
  }

  function pickCase(index) {
    const cases = page.description.cases;
    page.caseIndex = index;
    $('case').selectedIndex = index + 1;
    describeCase();
    changed(Module.applyCase(index >= 0 ? cases[index].name : ''));
    if (page.view !== 'yours') showView();
  }
  page.pickCase = (name) => pickCase(page.description.cases.findIndex((c) => c.name === name));

  // ---- Keys and the mouse, as the window has them ----
  // ?embed (a deck's live slide): the picture and its parameters only, the picture drawn as large as its place allows
  // in the lab's proportions.
  const embedded = query.has('embed');
  if (embedded) document.body.classList.add('embedded');
  function fitToView() {
    const d = page.description;
    const room = $('view').clientWidth, tall = window.innerHeight - 80;
    const scale = Math.max(1, Math.min(room / d.width, tall / d.height));
    return drawAt(Math.round(d.width * scale), Math.round(d.height * scale));
  }

  // The lab draws at width x height pixels, shown at that size in CSS pixels unless `shown` says otherwise.
  function drawAt(width, height, shown) {
    const error = Module.resize(width, height);
    $('canvas').style.width = shown ? shown[0] : width + 'px';
    $('canvas').style.height = shown ? shown[1] : height + 'px';
    changed(error);
    return error;
  }

  // Full screen (F, or the button): the picture at the screen's own size in device pixels, drawn by the lab at that
  // size; on leaving, the lab's size (or ?size=) again.
  function fullScreen() {
    if (document.fullscreenElement) document.exitFullscreen();
    else $('picture').requestFullscreen().catch((e) => say('Full screen refused by the browser: ' + e.message, 'warning'));
  }

  function sizeToScreen() {
    const d = page.description;
    if (document.fullscreenElement !== $('picture')) {  // left: the lab's size, or a slide's fitted one
      if (!(embedded ? fitToView() : drawAt(d.width, d.height))) say(d.title + ' on ' + d.gl);
      return;
    }
    const width = Math.round(window.innerWidth * devicePixelRatio), height = Math.round(window.innerHeight * devicePixelRatio);
    if (!drawAt(width, height, ['100vw', '100vh'])) say('full screen: the picture at ' + width + 'x' + height + ' (F or Esc leaves)');
  }
  page.fullScreen = fullScreen;

  function bindKeysAndMouse() {
    const canvas = $('canvas');
    $('fullscreen-button').addEventListener('click', fullScreen);
    document.addEventListener('fullscreenchange', sizeToScreen);
    $('compare-at').addEventListener('input', cutOverlay);
    $('compare-button').addEventListener('click', nextView);
    let drag = null;
    canvas.addEventListener('pointerdown', (e) => {
      drag = { x: e.clientX, y: e.clientY };
      canvas.setPointerCapture(e.pointerId);
      canvas.focus();
    });
    canvas.addEventListener('pointerup', () => { drag = null; });
    canvas.addEventListener('pointermove', (e) => {
      if (!drag) return;
      const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
      drag = { x: e.clientX, y: e.clientY };
      changed(Module.orbit(dx, dy, 0));
    });
    canvas.addEventListener('wheel', (e) => {
      e.preventDefault();
      changed(Module.orbit(0, 0, e.deltaY < 0 ? 1 : -1));
    }, { passive: false });
    document.addEventListener('keydown', (e) => {
      const target = e.target;
      if (target.closest && (target.closest('.CodeMirror') || ['INPUT', 'SELECT', 'TEXTAREA'].includes(target.tagName))) return;
      const key = e.key.length === 1 ? e.key.toUpperCase() : e.key;
      if (key === 'C') pickCase((page.caseIndex + 1) % page.description.cases.length);
      else if (key === 'V') nextView();
      else if (key === 'F') fullScreen();
      else if (key === 'S') savePicture();
      else if (key === 'U') document.body.classList.toggle('panel-hidden');
      else if (key === ' ') togglePlay();
      else return;
      e.preventDefault();
    });
  }

  function togglePlay() {
    const axis = page.description.params.find((p) => p.animated);
    if (!axis) {
      say(page.description.lab + ' has no animated parameter to play', 'warning');
      return;
    }
    page.playing = !page.playing;
    lastTime = 0;
    say((page.playing ? 'playing ' : 'paused ') + axis.name);
  }

  function savePicture() {
    $('canvas').toBlob((blob) => {
      const a = document.createElement('a');
      a.href = URL.createObjectURL(blob);
      a.download = lab + '-screenshot.png';
      a.click();
    });
  }

  // V: yours, then the current case's golden image, then yours | golden | difference (the self-check's compare view).
  function nextView() {
    if (page.checking) {
      say('The self-check is drawing its cases: compare after it', 'warning');
      return;
    }
    const views = ['yours', 'golden', 'compare'];
    page.view = views[(views.indexOf(page.view) + 1) % views.length];
    showView();
  }

  // golden: the golden image over yours, cut where the slider is (yours on its left, the golden on its right); compare:
  // the composite in the picture's place.
  function showView() {
    const overlay = $('overlay');
    const c = page.description.cases[page.caseIndex];
    const slider = $('compare-slider');
    overlay.classList.toggle('composite', page.view === 'compare');
    $('canvas').classList.toggle('under-composite', page.view === 'compare');
    if (page.view === 'yours' || !c || !c.todo || !window.gsvSelfCheck) {
      overlay.hidden = true;
      slider.hidden = true;
      $('canvas').classList.remove('under-composite');
      if (page.view !== 'yours') say('V compares a graded case with its golden image: pick one with C first', 'warning');
      page.view = 'yours';
      return;
    }
    const url = page.view === 'golden' ? window.gsvSelfCheck.goldenUrl(c.name) : window.gsvSelfCheck.compareUrl(c.name);
    overlay.src = url;
    overlay.hidden = false;
    slider.hidden = page.view !== 'golden';
    cutOverlay();
    say('view: ' + (page.view === 'golden' ? 'yours left of the slider, the golden image of ' + c.name + ' right of it'
                                          : 'yours | golden | difference, ' + c.name));
  }

  function cutOverlay() {
    const at = Number($('compare-at').value);
    $('overlay').style.clipPath = page.view === 'golden' ? 'inset(0 0 0 ' + at + '%)' : '';
  }

  // ---- A lost WebGL context: restored where the browser gives it back, else one line; the edits are kept ----
  function watchContext(canvas) {
    canvas.addEventListener('webglcontextlost', (e) => {
      e.preventDefault();  // asks the browser to restore it
      page.lost = true;
      say('The browser took the WebGL context away (too many pages using the GPU, or a driver reset): waiting for it ' +
          'to come back. Your edits are kept; reload the page if the picture does not return.', 'error');
      if (window.gsvEditor) window.gsvEditor.saveAll();
    });
    canvas.addEventListener('webglcontextrestored', () => {
      say('The WebGL context came back, but the lab\'s GPU objects are gone with the old one: reload the page to go ' +
          'on (your edits are kept in this browser).', 'error');
    });
  }
})();
