#!/usr/bin/env python3
"""One list of labs, taken from the folders (cmake/lab_list.cmake; labs/README.md, "Adding a lab"):
  1. the build's list (BUILD/labs.json, which the tests read when they run) is the kit's folders' as CMake reads them
     now (`cmake -P cmake/lab_list.cmake`), and those are the folders solutions/labNN_name/;
  2. no file of the kit outside the labs' own folders lists them: no line of code, build file, script or CI file names
     every lab, no test file has a test case a lab, and no document counts them ("seven labs");
  3. tests/lab_rules.json states each rule once, with what to do.
Usage: check_lab_list.py KIT BUILD        exit 0: holds, 1: it does not (each breach a line)"""
import json
import os
import re
import subprocess
import sys

# A lab's own files, which name it: its folders, its data (and its deck, slides/NN-name.md: below); the kit's data.
OWN = re.compile(r"^(solutions|labs|reference|data|third_party|grader/(cases|hidden|golden)|tests/(mutants|heldout))/")
SKIP_DIRS = {".git", "node_modules", "__pycache__"}
CODE = re.compile(r"(\.(cpp|h|py|sh|js|cmake|yml|yaml|json|in)|CMakeLists\.txt|/kit)$")
NUMBERS = ["zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve",
           "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen", "twenty"]


def kit_files(kit, ids):
    decks = re.compile(r"^slides/(" + "|".join(lab[3:] for lab in ids) + r")-[^/]*\.md$")
    for folder, dirs, files in os.walk(kit):
        rel_folder = os.path.relpath(folder, kit)
        dirs[:] = [d for d in dirs if d not in SKIP_DIRS and not (rel_folder == "." and d.startswith("build"))]
        for name in files:
            rel = os.path.normpath(os.path.join(rel_folder, name)).replace(os.sep, "/")
            if not OWN.search(rel) and not (ids and decks.search(rel)):
                yield rel


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    kit, build = argv[1], argv[2]
    problems = []

    # 1. The build's list is the folders'.
    now = subprocess.run(["cmake", "-DGSV_KIT=" + kit, "-P", os.path.join(kit, "cmake", "lab_list.cmake")],
                         capture_output=True, text=True)
    if now.returncode != 0:
        print("check_lab_list: cmake/lab_list.cmake failed:\n" + now.stderr, file=sys.stderr)
        return 1
    labs = json.loads(now.stdout)["labs"]
    try:
        built = json.load(open(os.path.join(build, "labs.json")))["labs"]
    except (OSError, ValueError) as e:
        built = None
        problems.append(f"{build}/labs.json cannot be read ({e}): configure again")
    if built is not None and built != labs:
        problems.append(f"{build}/labs.json is not the kit's folders as they are now: configure again "
                        f"(built: {[lab['id'] for lab in built]}, folders: {[lab['id'] for lab in labs]})")
    folders = sorted(d for d in os.listdir(os.path.join(kit, "solutions"))
                     if re.fullmatch(r"lab[0-9][0-9]_.+", d) and os.path.isdir(os.path.join(kit, "solutions", d)))
    if [lab["dir"] for lab in labs] != folders:
        problems.append(f"the list {[lab['dir'] for lab in labs]} is not the folders of solutions/ {folders}")
    ids = [lab["id"] for lab in labs]

    # 2. Nothing else lists them.
    count_words = {str(len(ids)), NUMBERS[len(ids)] if len(ids) < len(NUMBERS) else str(len(ids))}
    count = re.compile(r"\b(" + "|".join(count_words) + r")\s+(numbered\s+)?labs\b", re.I)
    for rel in kit_files(kit, ids):
        path = os.path.join(kit, rel)
        try:
            text = open(path, encoding="utf-8").read()
        except (UnicodeDecodeError, OSError):
            continue
        if rel.endswith(".md"):
            for n, line in enumerate(text.splitlines(), 1):
                if count.search(line):
                    problems.append(f"{rel}:{n}: counts the labs ('{count.search(line).group(0)}'): say 'the labs' or "
                                    f"'every lab', so a lab added leaves it true")
            continue
        if not CODE.search("/" + rel):
            continue
        for n, line in enumerate(text.splitlines(), 1):
            if len(ids) > 1 and all(re.search(r"\b" + lab + r"\b", line) for lab in ids):
                problems.append(f"{rel}:{n}: names every lab, a list a lab added would miss: take it from the kit's "
                                f"list (cmake/lab_list.cmake; scripts/kit_labs.py; tests/lab_runner.h)")
        if rel.startswith("tests/") and rel.endswith(".cpp"):
            per_lab = re.findall(r'TEST_CASE\("(?:[a-z]+: )?(lab[0-9][0-9])\b', text)
            if len(ids) > 1 and set(ids) <= set(per_lab):
                problems.append(f"{rel}: a TEST_CASE for each lab: make them from the list (GSV_PER_LAB_TEST, tests/per_lab.h)")

    # 3. The rules, once.
    rules = json.load(open(os.path.join(kit, "tests", "lab_rules.json")))["rules"]
    names = [r.get("name") for r in rules]
    if len(set(names)) != len(names):
        problems.append(f"tests/lab_rules.json states a rule twice: {names}")
    for r in rules:
        if not r.get("says") or not r.get("do") or ("least" in r and not (isinstance(r["least"], int) and r["least"] > 0)):
            problems.append(f"tests/lab_rules.json: rule {r.get('name')} needs 'says', 'do' and a whole 'least' above 0")

    for problem in problems:
        print("check_lab_list: " + problem)
    print(f"check_lab_list: {len(ids)} labs ({', '.join(ids)}), from the folders; {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
