// The self-check's view: gsv-grade's table as the grader's code wrote it in the page (grader/src/app/page_self_check.cpp), and
// for each case that did not pass, yours | golden | the difference (and the known mistake it matches, with what went
// wrong), with compare's composite a click away.
'use strict';
window.gsvSelfCheck = (function () {
  const $ = (id) => document.getElementById(id);
  let description = null;
  const urls = new Map();

  function fileUrl(path) {
    if (urls.has(path)) URL.revokeObjectURL(urls.get(path));
    const url = URL.createObjectURL(new Blob([Module.FS.readFile(path)], { type: 'image/png' }));
    urls.set(path, url);
    return url;
  }

  function figure(caption, path) {
    const f = document.createElement('figure');
    const img = document.createElement('img');
    img.src = fileUrl(path);
    img.alt = caption;
    const c = document.createElement('figcaption');
    c.textContent = caption;
    f.append(img, c);
    return f;
  }

  // The result of a check: gsv-grade's table, and for each case that did not pass yours | golden | the difference.
  function show(result, label) {
    $('self-check-table').textContent = result.table;
    const rows = $('self-check-rows');
    rows.textContent = '';
    for (const r of result.results) {
      if (r.passed || !r.actual) continue;
      const block = document.createElement('div');
      const title = document.createElement('p');
      title.textContent = r.name + ' (' + r.todo + '): ' + r.status + ' — ' + r.detail;
      block.append(title);
      if (r.mistake) {
        // What went wrong: the known mistake this picture is (gsv-grade's self-check names it the same way).
        const said = document.createElement('p');
        said.className = 'mistake';
        said.textContent = 'What went wrong: ' + r.mistake + ' (' + r.mistake_todo + '; see "' + r.mistake_sheet + '" in the sheet)';
        block.append(said);
      }
      block.append(figure('yours', r.actual), figure('golden', golden(r.name)));
      if (r.diff) block.append(figure('over the tolerance', r.diff));
      if (r.mistake_picture) block.append(figure('the known mistake\'s picture (reduced)', r.mistake_picture));
      rows.append(block);
    }
    window.gsvPage.selfCheck = result;
    window.gsvPage.say('Self-check' + label + ': ' + result.score + ' of ' + result.max_score +
                       ' points (the table below is gsv-grade\'s)');
  }

  // All at once, for compare's view of one case (V) and for scripts: the page waits for it.
  function run(only) {
    const result = JSON.parse(Module.selfCheck(only || ''));
    window.gsvPage.changed('');  // the page's own values are back: draw them again
    if (result.error) {
      window.gsvPage.say('Self-check: ' + result.error, 'error');
      return result;
    }
    if (!only) show(result, '');
    return result;
  }

  // The buttons' check: every public case, or one TODO's (only = its id), a case at a time with a frame between them, so
  // the page says how far it is and never holds still for longer than a case. The page draws nothing else meanwhile
  // (lab.js), and neither its controls nor a rebuild (editor.js) change what is being checked.
  let running = null;
  function check(only) {
    if (running) return running;
    const label = only ? ' of ' + only : '';
    const progress = $('self-check-progress');
    const page = window.gsvPage;
    running = (async () => {
      const started = JSON.parse(Module.selfCheckStart(only || ''));
      if (started.error) {
        page.say('Self-check: ' + started.error, 'error');
        return started;
      }
      page.checking = true;
      $('controls').inert = true;
      document.querySelectorAll('.self-check-button').forEach((b) => { b.disabled = true; });
      progress.hidden = false;
      progress.max = started.cases.length;
      progress.value = 0;
      try {
        for (;;) {
          const step = JSON.parse(Module.selfCheckStep());
          if (step.error) break;
          progress.value = step.done;
          page.say('Self-check' + label + ': ' + step.done + ' of ' + step.total + ' cases (' + step.name +
                   (step.passed ? ', passed)' : ', not passed)'));
          await new Promise((resolve) => setTimeout(resolve, 0));  // the page gets a turn after each case
          if (step.done >= step.total) break;
        }
        const result = JSON.parse(Module.selfCheckFinish());
        if (result.error) page.say('Self-check: ' + result.error, 'error');
        else show(result, label);
        if (!result.error) markTodos(result);
        return result;
      } finally {
        page.checking = false;
        $('controls').inert = false;
        document.querySelectorAll('.self-check-button:not(.desktop-only)').forEach((b) => { b.disabled = false; });
        progress.hidden = true;
        page.changed('');  // the page's own values are back: draw them again
        running = null;
      }
    })();
    return running;
  }

  // Each TODO's row in the sheet's TODO table (sheet.js) shows its points in the last check that had its cases.
  function markTodos(result) {
    const points = new Map();
    for (const r of result.results) {
      const p = points.get(r.todo) || [0, 0];
      points.set(r.todo, [p[0] + r.points, p[1] + r.max_points]);
    }
    for (const [id, [got, max]] of points) {
      const cell = document.querySelector('#todo-table [data-todo="' + id + '"] .todo-result');
      if (!cell) continue;
      cell.textContent = got + ' / ' + max;
      cell.className = 'todo-result ' + (got === max ? 'passed' : 'failed');
    }
  }

  // One button per TODO; and what the page cannot check (cases past WebGL 2's ES 3.0: lab 05's compute shaders) said
  // under them with the points it implies, each such case marked in the case list, a TODO with only such cases greyed.
  function todoButtons() {
    const listed = JSON.parse(Module.selfCheckCases());
    if (listed.error) {
      window.gsvPage.say('Self-check: ' + listed.error, 'error');
      return;
    }
    const todos = [];
    for (const c of listed.cases) if (c.todo && !todos.includes(c.todo)) todos.push(c.todo);
    const holder = $('self-check-todos');
    for (const id of todos.sort()) {
      const own = listed.cases.filter((c) => c.todo === id);
      const b = Object.assign(document.createElement('button'), { type: 'button', className: 'self-check-button', textContent: id });
      b.title = 'Check the public cases of ' + id + ' only';
      if (own.every((c) => c.desktop_only)) {
        b.disabled = true;
        b.classList.add('desktop-only');
        b.title = id + '\'s cases need OpenGL ES ' + own[0].es + ', which WebGL 2 (ES 3.0) is not: check them on the desktop';
      }
      b.addEventListener('click', () => check(id));
      holder.append(b);
    }
    const desktop = listed.cases.filter((c) => c.desktop_only);
    const note = $('self-check-desktop');
    if (!desktop.length) return;
    const points = (list) => list.reduce((sum, c) => sum + c.points, 0);
    note.textContent = points(desktop) + ' of ' + points(listed.cases) + ' points are the desktop\'s to check: ' +
      desktop.map((c) => c.name + ' (' + c.todo + ', ES ' + c.es + ')').join(', ') +
      ' need more than WebGL 2 (OpenGL ES 3.0) has. Download your files and run gsv-grade --self-check for them.';
    for (const option of $('case').options) {
      const c = desktop.find((d) => d.name === option.value);
      if (c) option.textContent += ' — desktop only';
    }
  }

  function golden(name) { return '/kit/grader/golden/' + description.lab + '/' + name + '.png'; }

  return {
    attach(d) {
      description = d;
      $('run-self-check').addEventListener('click', () => check(''));
      todoButtons();
    },
    run,
    check,
    goldenUrl: (name) => fileUrl(golden(name)),
    compareUrl(name) {
      run(name);
      return fileUrl('/self-check/' + name + '/compare.png');
    },
  };
})();
