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

  function run(only) {
    const result = JSON.parse(Module.selfCheck(only || ''));
    window.gsvPage.changed('');  // the page's own values are back: draw them again
    if (result.error) {
      window.gsvPage.say('Self-check: ' + result.error, 'error');
      return result;
    }
    if (only) return result;
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
    window.gsvPage.say('Self-check: ' + result.score + ' of ' + result.max_score + ' points (the table below is gsv-grade\'s)');
    return result;
  }

  function golden(name) { return '/kit/grader/golden/' + description.lab + '/' + name + '.png'; }

  return {
    attach(d) {
      description = d;
      $('run-self-check').addEventListener('click', () => run(''));
    },
    run,
    goldenUrl: (name) => fileUrl(golden(name)),
    compareUrl(name) {
      run(name);
      return fileUrl('/self-check/' + name + '/compare.png');
    },
  };
})();
