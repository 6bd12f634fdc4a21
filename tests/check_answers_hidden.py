#!/usr/bin/env python3
"""No answer in the student's copy: every significant line of every //@solution block appears in no file of the
student edition (scripts/export-student.sh) but the TODO's own file.

A line is significant when, with all whitespace removed, it is at least MIN_CHARS characters long, is not a
comment, and does not also stand outside the solution blocks of its own file (there it is given code that the
starter keeps, by design). Lines are compared with all whitespace removed, so `a+b` finds `a + b`, also where
another file wraps it over two lines.

Two kinds of exception, each with its reason:
  - a later lab whose starter holds an earlier lab's answers, declared in the table "Answers a later lab holds"
    of labs/README.md (export-student.sh --labs refuses to release the later lab without the earlier one);
  - tests/answers_allowed.json: one line in one file, for one TODO, with why it may stay. An entry that no longer
    matches anything fails too, so the list cannot outlive what it excuses.

usage: check_answers_hidden.py KIT_ROOT [--edition DIR]   (without --edition, exports the kit to a temp folder)
Exit 0: no answer found; 1: answers found (listed); 2: usage or export error.
"""
import json
import os
import re
import subprocess
import sys
import tempfile
import time

MIN_CHARS = 25
TEXT_SUFFIXES = {".cpp", ".h", ".hpp", ".c", ".glsl", ".vert", ".frag", ".comp", ".geom", ".md", ".txt", ".cmake",
                 ".json", ".sh", ".py", ".yml", ".yaml", ".html", ".css", ".js", ".in", ".network", ""}
BLOCK_START = re.compile(r"^\s*//@solution\s+(L\d\d-T\d+)\s*$")
HELD_ROW = re.compile(r"^\|\s*(lab\d\d)\s*\|\s*(lab\d\d)\s*\|\s*(.+?)\s*\|")


def squeeze(text):
    return re.sub(r"\s+", "", text)


def is_comment(stripped):
    return stripped.startswith(("//", "/*", "*", "#include", "#pragma"))


def solution_lines(path):
    """(todo id, line number, text) of each significant line of the file's solution blocks."""
    lines = open(path, encoding="utf-8").read().splitlines()
    inside, todo, answer, outside = False, None, [], set()
    in_solution = False
    for number, line in enumerate(lines, 1):
        stripped = line.strip()
        start = BLOCK_START.match(line)
        if start:
            inside, in_solution, todo = True, True, start.group(1)
            continue
        if stripped == "//@starter":
            in_solution = False
            continue
        if stripped == "//@end":
            inside = in_solution = False
            continue
        if inside and in_solution:
            answer.append((todo, number, line))
        elif inside:  # a starter line: the student's own file has it without the leading //
            outside.add(squeeze(stripped[2:] if stripped.startswith("//") else stripped))
        else:
            outside.add(squeeze(stripped))
    found = []
    for todo, number, line in answer:
        key = squeeze(line)
        if len(key) < MIN_CHARS or is_comment(line.strip()) or key in outside:
            continue
        found.append((todo, number, line.strip(), key))
    return found


def lab_dirs(root):
    sys.path.insert(0, os.path.join(root, "scripts"))
    import kit_labs  # the kit's list of labs (cmake/lab_list.cmake)
    return {lab["id"]: lab["dir"] for lab in kit_labs.labs(root)}


def held_table(root):
    """(later lab, earlier lab, file name) rows of labs/README.md's table of answers a later lab holds."""
    rows = set()
    for line in open(os.path.join(root, "labs", "README.md"), encoding="utf-8"):
        m = HELD_ROW.match(line)
        if m:
            for name in re.findall(r"`([^`]+)`", m.group(3)):
                rows.add((m.group(1), m.group(2), name))
    return rows


def edition_files(edition):
    for folder, _, names in os.walk(edition):
        for name in names:
            path = os.path.join(folder, name)
            if os.path.splitext(name)[1] in TEXT_SUFFIXES and not os.path.islink(path):
                try:
                    text = open(path, encoding="utf-8").read()
                except UnicodeDecodeError:
                    continue
                yield os.path.relpath(path, edition), text


def main():
    args = sys.argv[1:]
    if not args or args[0].startswith("-"):
        print(__doc__.strip().splitlines()[-2], file=sys.stderr)
        return 2
    root = os.path.abspath(args[0])
    edition = args[args.index("--edition") + 1] if "--edition" in args else None
    started = time.time()
    tmp = None
    if edition is None:
        tmp = tempfile.TemporaryDirectory(prefix="gsv-answers-")
        edition = os.path.join(tmp.name, "edition")
        env = dict(os.environ)
        run = subprocess.run([os.path.join(root, "scripts", "export-student.sh"), "--include-untracked", edition],
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
        if run.returncode != 0:
            print("check_answers_hidden: the export failed:\n" + run.stdout, file=sys.stderr)
            return 2

    dirs = lab_dirs(root)
    lab_of_dir = {d: lab for lab, d in dirs.items()}
    held = held_table(root)
    allowed = json.load(open(os.path.join(root, "tests", "answers_allowed.json"), encoding="utf-8"))["allowed"]
    used = [False] * len(allowed)

    answers = []  # (todo, solution file, line number, text, key)
    solutions = os.path.join(root, "solutions")
    for folder, _, names in os.walk(solutions):
        for name in sorted(names):
            path = os.path.join(folder, name)
            if os.path.splitext(name)[1] in TEXT_SUFFIXES:
                for todo, number, text, key in solution_lines(path):
                    answers.append((todo, os.path.relpath(path, root), number, text, key))

    files = [(rel, text, [squeeze(l) for l in text.splitlines()], squeeze(text)) for rel, text in edition_files(edition)]
    problems = []
    for todo, source, number, text, key in answers:
        own = "labs/" + os.path.relpath(source, "solutions")
        for rel, _, lines, whole in files:
            if rel == own or key not in whole:
                continue
            where = [i for i, l in enumerate(lines, 1) if key in l]
            at = f"{rel}:{where[0]}" if where else f"{rel} (across lines)"
            parts = rel.split("/")
            todo_lab = "lab" + todo[1:3]
            if len(parts) == 3 and parts[0] == "labs" and parts[1] in lab_of_dir and \
                    (lab_of_dir[parts[1]], todo_lab, parts[2]) in held:
                continue
            excused = False
            for i, entry in enumerate(allowed):
                if entry["todo"] == todo and entry["file"] == rel and squeeze(entry["line"]) in key:
                    used[i] = excused = True
            if not excused:
                problems.append(f"{todo}: {source}:{number} `{text}` is also in {at}")
    for entry, was_used in zip(allowed, used):
        if not was_used:
            problems.append(f"tests/answers_allowed.json: {entry['todo']} in {entry['file']} matches nothing any more; "
                            "remove the entry")

    for p in problems:
        print("check_answers_hidden: " + p)
    todos = len({a[0] for a in answers})
    print(f"check_answers_hidden: {len(answers)} answer lines of {todos} TODOs searched in {len(files)} text files of "
          f"the student edition, {len(problems)} found, in {time.time() - started:.1f} s")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
