// The lab sheet in the page: the lab's README.md, the same sheet as in the kit's folder, rendered with marked (npm) at
// the foot of the page, and its TODO table (id, file, what to write, the cases) above the editor's tabs: an id opens
// the file that holds it, and its row keeps the result of that TODO's last self-check (self_check.js).
'use strict';
window.gsvSheet = (function () {
  const $ = (id) => document.getElementById(id);

  // The sheet's table whose first column is the TODO id.
  function todoTable(root) {
    return Array.from(root.querySelectorAll('table')).find((t) => {
      const first = t.querySelector('th');
      return first && first.textContent.trim().toLowerCase() === 'id';
    });
  }

  function openTodo(id) {
    const editor = window.gsvEditor;
    const f = editor && editor.files().find((g) => g.todos && g.todos.includes(id));
    if (f) editor.show(f.name);
    else if (window.gsvPage) window.gsvPage.say(id + ' is in the lab\'s C++: do it in the desktop build (the page runs the kit\'s starter)');
    $('code').scrollIntoView({ block: 'nearest' });
  }

  async function load() {
    const text = $('sheet-text');
    let markdown;
    try {
      const reply = await fetch('README.md');
      if (!reply.ok) throw new Error('HTTP ' + reply.status);
      markdown = await reply.text();
    } catch (e) {
      text.textContent = 'The lab sheet (README.md) did not load: ' + e.message;
      return;
    }
    // The kit's own sheet, not anything a student typed: its HTML goes in as marked makes it.
    text.innerHTML = marked.parse(markdown);
    const table = todoTable(text);
    if (!table) return;
    const copy = $('todo-table');
    copy.innerHTML = table.innerHTML;
    const head = copy.querySelector('thead tr');
    if (head) head.append(Object.assign(document.createElement('th'), { textContent: 'self-check' }));
    for (const row of copy.querySelectorAll('tbody tr')) {
      const cell = row.querySelector('td');
      const id = cell ? cell.textContent.trim() : '';
      if (!/^L\d\d-T\d+$/.test(id)) continue;
      row.dataset.todo = id;
      const link = Object.assign(document.createElement('a'), { href: '#code', textContent: id, title: 'Open the file that holds ' + id });
      link.addEventListener('click', (e) => { e.preventDefault(); openTodo(id); });
      cell.textContent = '';
      cell.append(link);
      const check = Object.assign(document.createElement('td'), { className: 'todo-check' });
      const button = Object.assign(document.createElement('button'), { type: 'button', className: 'self-check-button', textContent: 'check' });
      button.title = 'Check the public cases of ' + id + ' only';
      button.addEventListener('click', () => { if (window.gsvSelfCheck) window.gsvSelfCheck.check(id); });
      check.append(button, ' ', Object.assign(document.createElement('span'), { className: 'todo-result' }));
      row.append(check);
    }
  }

  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', load);
  else load();
  return { load };
})();
