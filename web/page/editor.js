// The student's shaders in the page: a tab per GLSL file of the lab's folder (Debian's CodeMirror 5, its C-like mode's
// GLSL), each edit written over the file in the page's memory file system and every program rebuilt from it, as the
// window's hot reload does on a save: a broken edit shows its error at the student's file and line, and the last good
// program keeps drawing. It rebuilds on Ctrl+Enter (Cmd+Enter) at once, and by itself after a pause long enough not to
// catch a line half typed. A tab names the TODOs its file holds; a file the page never compiles (a compute shader:
// WebGL 2 has none) says so and is not the one the editor opens on. Edits are kept in the browser's storage; download
// gives the lab's folder as gsv-grade takes it.
'use strict';
window.gsvEditor = (function () {
  const $ = (id) => document.getElementById(id);
  const shaderFile = /\.(vert|frag|glsl|comp)$/;
  // A pause this long after the last keystroke rebuilds: at 300 ms a half-typed line flashed an error.
  const kPauseMs = 1500;
  // Compute shaders: the page is WebGL 2 (OpenGL ES 3.0), which has none; the lab takes its ES path there.
  const notCompiledHere = (name) => /\.comp$/.test(name);
  const files = [];  // {name, path, starter, doc, tab}
  let labDir = '', folderName = '', current = null, onResult = null, editor = null, timer = 0, storageOk = true;
  const pending = new Set();
  const storageKey = (name) => 'gsv-web:' + location.pathname + ':' + name;
  const page = () => window.gsvPage;

  // The lab's own folder in the page's files: the starter's (labs/) on the site, the reference's on the tests' pages.
  function findLabDir(root) {
    for (const top of ['labs', 'solutions']) {
      try {
        const entries = Module.FS.readdir(root + '/' + top).filter((e) => e !== '.' && e !== '..');
        if (entries.length) return top + '/' + entries[0];
      } catch (e) { /* not in this page */ }
    }
    return '';
  }

  function readStored(name) {
    try {
      return localStorage.getItem(storageKey(name));
    } catch (e) {
      storageRefused(e);
      return null;
    }
  }

  function storageRefused(e) {
    if (!storageOk) return;
    storageOk = false;
    $('storage-note').textContent = 'This browser ' + (e && e.name === 'QuotaExceededError' ? 'has no room left' : 'refuses') +
      ' to keep your edits (' + (e && e.name || e) + '): they stay in the editor while this page is open, and ' +
      '"Download your files" is their only copy.';
  }

  function store(file) {
    const text = file.doc.getValue();
    try {
      if (text === file.starter) localStorage.removeItem(storageKey(file.name));
      else localStorage.setItem(storageKey(file.name), text);
      if (!storageOk) return;
      $('storage-note').textContent = '';
    } catch (e) {
      storageRefused(e);
    }
  }

  function restoreIntoFiles(root) {
    labDir = findLabDir(root);
    folderName = labDir.split('/').pop();
    let restored = 0;
    for (const name of Module.FS.readdir(root + '/' + labDir).filter((n) => shaderFile.test(n)).sort()) {
      const path = root + '/' + labDir + '/' + name;
      const file = { name, path, starter: Module.FS.readFile(path, { encoding: 'utf8' }) };
      file.text = readStored(name) ?? file.starter;
      if (file.text !== file.starter) {
        Module.FS.writeFile(path, file.text);
        restored++;
      }
      file.applied = file.text;  // what the page's files hold
      files.push(file);
    }
    return restored;
  }

  function writeStarterFiles() {
    for (const f of files) Module.FS.writeFile(f.path, f.starter);
  }

  function writeEditedFiles() {
    for (const f of files) Module.FS.writeFile(f.path, f.text);
  }

  function open(description, resultCallback) {
    onResult = resultCallback;
    const tabs = $('tabs');
    editor = CodeMirror($('code'), { lineNumbers: true, indentUnit: 4, mode: 'x-shader/x-fragment',
                                     extraKeys: { 'Ctrl-Enter': rebuildNow, 'Cmd-Enter': rebuildNow } });
    for (const f of files) {
      f.doc = CodeMirror.Doc(f.text, /\.vert$/.test(f.name) ? 'x-shader/x-vertex' : 'x-shader/x-fragment');
      f.tab = document.createElement('button');
      f.tab.type = 'button';
      f.tab.role = 'tab';
      f.tab.textContent = f.name;
      // The TODO ids the starter's file holds, on its tab (lab 06 has 23 files, six with TODOs).
      f.todos = Array.from(new Set((f.starter.match(/TODO\((L\d\d-T\d+)\)/g) || []).map((t) => t.slice(5, -1))));
      if (f.todos.length) {
        f.tab.classList.add('todo');
        f.tab.append(' ', Object.assign(document.createElement('span'), { className: 'todo-ids', textContent: f.todos.join(' ') }));
      }
      if (notCompiledHere(f.name)) {
        f.tab.classList.add('not-compiled');
        f.tab.title = 'Not compiled in this page: WebGL 2 has no compute shaders, so the page takes the lab\'s other path. ' +
                      'This file runs in the desktop build.';
      }
      f.tab.addEventListener('click', () => show(f));
      tabs.append(f.tab);
      f.doc.on('change', () => {
        edited(f, f.doc.getValue());
        if (f.text === f.applied) return;  // already in the page (an opened file: CodeMirror tells a detached doc's change late)
        pending.add(f);
        clearTimeout(timer);
        timer = setTimeout(applyPending, kPauseMs);
      });
      f.tab.classList.toggle('edited', f.text !== f.starter);
    }
    // The first file with a TODO that the page compiles; else the first the page compiles.
    const first = files.find((f) => f.todos.length && !notCompiledHere(f.name)) || files.find((f) => !notCompiledHere(f.name)) || files[0];
    if (first) show(first);
    $('download').addEventListener('click', download);
    $('open').addEventListener('change', (e) => openFiles(Array.from(e.target.files)).then(() => { e.target.value = ''; }));
    $('revert').addEventListener('click', () => {
      if (!current) return;
      current.doc.setValue(current.starter);
      rebuildNow();
    });
    // Edits made before a reload that do not build: the lab started from the starter, so say why now.
    if (files.some((f) => f.text !== f.starter)) reload();
  }

  // A file's new text: its tab marked where it differs from the starter, and kept at once (a reload within the
  // rebuild's pause keeps the edit).
  function edited(f, text) {
    f.text = text;
    f.tab.classList.toggle('edited', f.text !== f.starter);
    store(f);
  }

  function show(f) {
    current = f;
    editor.swapDoc(f.doc);
    for (const g of files) g.tab.setAttribute('aria-selected', String(g === f));
    $('not-compiled-note').textContent = notCompiledHere(f.name)
      ? f.name + ' is not compiled in this page (WebGL 2 has no compute shaders): edit it here, download, and run it ' +
        'in the desktop build; the page draws with the lab\'s other files.'
      : '';
    markError();
  }

  // Every file changed since the last rebuild is written, then one rebuild: an opened folder lands as a whole.
  function applyPending() {
    if (window.gsvPage && window.gsvPage.checking) {  // not halfway through a self-check: after it
      clearTimeout(timer);
      timer = setTimeout(applyPending, 200);
      return;
    }
    for (const f of pending) {
      Module.FS.writeFile(f.path, f.text);
      f.applied = f.text;  // stored when it was edited
    }
    pending.clear();
    reload();
  }

  let lastError = '';
  function reload() {
    lastError = Module.reloadShaders();
    // The kit's root in the page is /kit: the student's path is what follows it.
    $('shader-error').textContent = lastError.split('/kit/').join('');
    page().shaderError = lastError;
    markError();
    if (onResult) onResult(lastError);
    page().changed('');
  }

  // The line the error names, in the tab of the file it names. Kept by its line handle, not its number: lines typed
  // above it move it, and a mark removed by number stayed on the moved line after the fix.
  function markError() {
    for (const f of files) {
      if (f.marked) f.doc.removeLineClass(f.marked, 'background', 'error-line');
      f.marked = null;
    }
    const m = /([\w./-]+\.(?:vert|frag|glsl|comp)):(\d+)/.exec(lastError);
    if (!m) return;
    const f = files.find((g) => m[1].endsWith('/' + g.name) || m[1] === g.name);
    if (!f) return;
    f.marked = f.doc.addLineClass(Math.min(Math.max(0, Number(m[2]) - 1), f.doc.lineCount() - 1), 'background', 'error-line');
  }

  function saveAll() {
    for (const f of files) if (f.doc) store(f);
  }

  // The lab's folder as gsv-grade takes it from a submission: labs/<lab folder>/ with every file of it, the shaders
  // as edited here.
  function download() {
    const zip = new JSZip();
    const folder = zip.folder('labs').folder(folderName);
    const root = '/kit/' + labDir;
    for (const name of Module.FS.readdir(root).filter((n) => n !== '.' && n !== '..')) {
      const edited = files.find((f) => f.name === name);
      folder.file(name, edited ? edited.doc.getValue() : Module.FS.readFile(root + '/' + name));
    }
    return zip.generateAsync({ type: 'blob' }).then((blob) => {
      const a = document.createElement('a');
      a.href = URL.createObjectURL(blob);
      a.download = page().lab + '-' + folderName + '.zip';
      a.click();
      return blob;
    });
  }

  // A zip made by download (or any zip with the lab's folder in it), or the shader files themselves.
  async function openFiles(chosen) {
    const loaded = [], refused = [];
    const take = (name, text) => {
      const f = files.find((g) => g.name === name);
      if (!f) return false;
      f.doc.setValue(text);
      // Taken now, not on the doc's change event, which CodeMirror fires late for a tab not shown.
      edited(f, text);
      pending.add(f);
      loaded.push(name);
      return true;
    };
    for (const file of chosen) {
      if (/\.zip$/i.test(file.name)) {
        let zip;
        try {
          zip = await JSZip.loadAsync(file);
        } catch (e) {
          refused.push(file.name + ' (not a zip file JSZip can read)');
          continue;
        }
        const inLab = Object.values(zip.files).filter((e) => !e.dir && e.name.split('/').slice(-2, -1)[0] === folderName);
        for (const entry of inLab) {
          const name = entry.name.split('/').pop();
          if (shaderFile.test(name)) take(name, await entry.async('string'));
        }
        if (!inLab.length) refused.push(file.name + ' (it has no ' + folderName + '/ folder)');
      } else if (!take(file.name, await file.text())) {
        refused.push(file.name);
      }
    }
    // Files opened are not typing: rebuilt at once, as one.
    if (loaded.length) rebuildNow();
    const names = files.map((f) => f.name).join(', ');
    if (refused.length)
      page().say('Not opened: ' + refused.join(', ') + ' — this page takes ' + folderName + '\'s shader files (' + names +
                 ') or a zip of its folder; nothing else was changed.', 'warning');
    else if (loaded.length) page().say('Opened ' + loaded.join(', '));
    return { loaded, refused };
  }

  function rebuildNow() {
    clearTimeout(timer);
    applyPending();
  }

  return { restoreIntoFiles, writeStarterFiles, writeEditedFiles, open, saveAll, download, openFiles, rebuildNow,
           files: () => files, show: (name) => show(files.find((f) => f.name === name)) };
})();
