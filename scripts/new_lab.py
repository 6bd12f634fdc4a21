#!/usr/bin/env python3
"""scripts/kit new-lab NN NAME [TITLE]: lays out a minimal lab in the kit's own folders (labs/README.md, "Adding a
lab"): solutions/labNN_NAME/ (lab.cpp drawing one full-screen quad, shade.frag with the lab's one TODO, the sheet
README.md, lab.json), grader/cases/labNN.json (one case) and slides/NN-NAME.md (a deck). It builds, its starter paints
magenta, and no other file of the kit changes: the build, the tests, the CI files and the scripts take the lab from its
folder (cmake/lab_list.cmake). Then it says what to run next.

    new_lab.py [--kit DIR] NN NAME [TITLE]     NN: 01..99, a number no lab has; NAME: a-z, 0-9 and _ (isolines)
"""
import os
import re
import sys

KIT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TEMPLATES = os.path.join(KIT, "scripts", "new_lab")


def fail(message):
    print("new-lab: " + message, file=sys.stderr)
    sys.exit(2)


def main(argv):
    kit = KIT
    if len(argv) >= 2 and argv[0] == "--kit":
        kit, argv = os.path.abspath(argv[1]), argv[2:]
    if len(argv) not in (2, 3):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    number, name = argv[0], argv[1]
    if not re.fullmatch(r"[0-9]{2}", number) or number == "00":
        fail(f"the lab's number is two digits, 01 to 99, not '{number}'")
    if not re.fullmatch(r"[a-z][a-z0-9_]*", name):
        fail(f"the lab's name is lower-case letters, digits and _, starting with a letter, not '{name}'")
    lab, folder = "lab" + number, f"lab{number}_{name}"
    title = argv[2] if len(argv) == 3 else name.replace("_", " ").capitalize()
    if '"' in title or "\\" in title or "\n" in title:
        fail("the title holds no quote, backslash or line break")
    for parent in ("solutions", "labs"):
        taken = [d for d in sorted(os.listdir(os.path.join(kit, parent))) if d.startswith(lab + "_")] \
            if os.path.isdir(os.path.join(kit, parent)) else []
        if taken:
            fail(f"{lab} is taken: {parent}/{taken[0]}/ (give another number)")
    if not os.path.isdir(os.path.join(kit, "solutions")):
        fail(f"no solutions/ in {kit}: a lab is added to the instructor's kit, not the student edition")
    words = [w for w in re.split(r"[_0-9]+", name) if w]
    values = {"NN": number, "ID": lab, "DIR": folder, "NAME": name, "TITLE": title,
              "CLASS": "".join(w.capitalize() for w in words) + "Lab"}
    files = [("lab.cpp.in", f"solutions/{folder}/lab.cpp"), ("shade.frag.in", f"solutions/{folder}/shade.frag"),
             ("README.md.in", f"solutions/{folder}/README.md"), ("lab.json.in", f"solutions/{folder}/lab.json"),
             ("cases.json.in", f"grader/cases/{lab}.json"), ("deck.md.in", f"slides/{number}-{name}.md")]
    for _, path in files:
        if os.path.exists(os.path.join(kit, path)):
            fail(f"{path} exists already: {lab} is half made (remove what is there, or finish it by hand)")
    decks = [d for d in os.listdir(os.path.join(kit, "slides")) if d.startswith(number + "-") and d.endswith(".md")]
    if decks:
        fail(f"slides/{decks[0]} is lab {number}'s deck already (give another number)")
    for template, path in files:
        with open(os.path.join(TEMPLATES, template), encoding="utf-8") as f:
            text = f.read()
        text = re.sub(r"@([A-Z]+)@", lambda m: values[m.group(1)], text)
        os.makedirs(os.path.dirname(os.path.join(kit, path)), exist_ok=True)
        with open(os.path.join(kit, path), "w", encoding="utf-8") as f:
            f.write(text)
        print(f"new-lab: wrote {path}")
    print(f"""new-lab: {lab} is laid out; nothing else in the kit changed. Next (labs/README.md, "Adding a lab"):
  1. scripts/kit starters                  its starter, labs/{folder}/, generated from solutions/{folder}/
  2. cmake --build build --target {lab} {lab}_solution
     build/bin/{lab}                        the starter: magenta until L{number}-T1 is written
  3. build/bin/gsv-grade --update-goldens --labs {lab}
  4. scripts/kit check-lab {lab}            what it still lacks, and what to do""")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
