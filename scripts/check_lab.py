#!/usr/bin/env python3
"""scripts/kit check-lab LAB: is the lab ready to hand out? Runs, in order,
  1. starters    labs/<dir>/ is what solutions/<dir>/ generates (gsv-make-starters --check)
  2. goldens     every public case has its golden image, the known mistakes their pictures
  3. self-check  both ways against the goldens: the reference full marks, the starter none
  4. margins     every public case meets the margin bar on every implementation here, and every known mistake
                 loses points on a case it must fail (gsv-margins --check --fail-if-missed)
  5. mistakes    the known mistakes per TODO, the held-out ones, the hidden cases
then names each rule the lab misses and what to do. The rules and their numbers are tests/lab_rules.json's, the
file the tests read them from. Exit 0: every step passed and every rule is met; 1: not; 2: usage.

    check_lab.py LAB [--kit DIR] [--bin DIR] [--tools DIR] [--rules-only]
      --kit   the kit (default: this one)   --bin   its build's bin/ (default: KIT/build/bin)
      --tools where gsv-make-starters, gsv-grade and gsv-margins are (default: --bin; any build of the kit's tools)
      --rules-only   only the rules that need no run (counts and files): quick, and without a build
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import kit_labs  # noqa: E402  (the kit's list of labs)


def say(line=""):
    print(line, flush=True)


def run(argv, **kw):
    return subprocess.run([str(a) for a in argv], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, **kw)


def tail(text, lines=12):
    return "\n".join("      " + line for line in text.strip().splitlines()[-lines:])


def todo_ids(folder):
    """Each TODO id of a reference folder with whether it is in C++ (as tools/starter.h reads the markers)."""
    todos = {}
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name)
        if not os.path.isfile(path):
            continue
        with open(path, encoding="utf-8", errors="replace") as f:
            for line in f:
                m = re.match(r"\s*//@solution\s+(\S+)", line)
                if m:
                    cpp = os.path.splitext(name)[1] in (".cpp", ".h", ".hpp", ".cc")
                    todos[m.group(1)] = todos.get(m.group(1), False) or cpp
    return todos


def read_json(path):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def main(argv):
    args, kit, bin_dir, tools_dir, rules_only = [], os.path.dirname(HERE), None, None, False
    i = 0
    while i < len(argv):
        if argv[i] in ("--kit", "--bin", "--tools") and i + 1 < len(argv):
            value = os.path.abspath(argv[i + 1])
            if argv[i] == "--kit":
                kit = value
            elif argv[i] == "--bin":
                bin_dir = value
            else:
                tools_dir = value
            i += 2
        elif argv[i] == "--rules-only":
            rules_only, i = True, i + 1
        elif argv[i].startswith("-"):
            print(__doc__.strip(), file=sys.stderr)
            return 2
        else:
            args.append(argv[i])
            i += 1
    if len(args) != 1:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    lab = args[0]
    bin_dir = bin_dir or os.path.join(kit, "build", "bin")
    listed = {entry["id"]: entry for entry in kit_labs.labs(kit)}
    if lab not in listed:
        print(f"check-lab: no lab '{lab}' in {kit} (its labs: {', '.join(listed)}; a lab is a folder "
              f"solutions/labNN_name/: scripts/kit new-lab NN name lays one out)", file=sys.stderr)
        return 2
    folder = listed[lab]["dir"]
    rules = read_json(os.path.join(kit, "tests", "lab_rules.json"))["rules"]
    least = {r["name"]: r.get("least") for r in rules}
    missed = set()     # rules the lab misses
    failures = []      # steps that failed, with what to do
    solution_dir, starter_dir = os.path.join(kit, "solutions", folder), os.path.join(kit, "labs", folder)
    cases_file = os.path.join(kit, "grader", "cases", lab + ".json")
    cases = (read_json(cases_file) or {}).get("cases", [])
    golden_dir = os.path.join(kit, "grader", "golden", lab)
    mutants = read_json(os.path.join(kit, "tests", "mutants", lab + ".json"))
    tools = {name: os.path.join(tools_dir or bin_dir, name) for name in ("gsv-make-starters", "gsv-grade", "gsv-margins")}
    if not rules_only:
        absent = [name for name, path in tools.items() if not os.access(path, os.X_OK)] + \
                 [b for b in [lab + "_solution"] + ([lab] if os.path.isdir(starter_dir) else [])
                  if not os.access(os.path.join(bin_dir, b), os.X_OK)]
        if absent:
            print(f"check-lab: {', '.join(absent)} not built in {bin_dir}: scripts/kit check-lab builds them "
                  f"(or cmake --build build --target {' '.join(absent)})", file=sys.stderr)
            return 2
    say(f"check-lab: {lab} ({folder}) in {kit}")

    # 1. Starters.
    if not os.path.isdir(starter_dir):
        failures.append(f"no starter labs/{folder}/: scripts/kit starters (gsv-make-starters --write) generates it")
        say("1. starters: none yet")
    elif rules_only:
        say("1. starters: not run (--rules-only)")
    else:
        check = run([tools["gsv-make-starters"], "--check", "--root", kit])
        stale = [line for line in check.stdout.splitlines() if line.startswith("STALE ") and f"/{folder}/" in line]
        if stale:
            failures.append(f"labs/{folder}/ is not what solutions/{folder}/ generates: scripts/kit starters")
            say("1. starters: stale\n" + tail("\n".join(stale)))
        else:
            say(f"1. starters: labs/{folder}/ is what solutions/{folder}/ generates")

    # 2. Goldens.
    no_golden = [c["name"] for c in cases if not os.path.isfile(os.path.join(golden_dir, c["name"] + ".png"))]
    no_pictures = mutants is not None and cases and not os.path.isfile(os.path.join(golden_dir, "mistakes.json"))
    if not cases:
        say(f"2. goldens: no public cases in grader/cases/{lab}.json")
    elif no_golden:
        missed.add("goldens")
        say(f"2. goldens: none for {len(no_golden)} of {len(cases)} public cases ({', '.join(no_golden[:5])}"
            f"{', ...' if len(no_golden) > 5 else ''})")
    elif no_pictures:
        missed.add("goldens")
        say(f"2. goldens: every public case has its golden; the known mistakes have no pictures "
            f"(grader/golden/{lab}/mistakes.json: build/bin/gsv-grade --update-mistakes --labs {lab})")
    else:
        say(f"2. goldens: every public case has its golden image")

    # 3. The self-check both ways, against the goldens.
    if rules_only:
        say("3. self-check: not run (--rules-only)")
    elif not cases or no_golden:
        say("3. self-check: not run (it grades against the goldens: render them first)")
    else:
        with tempfile.TemporaryDirectory(prefix="gsv-check-lab-") as tmp:
            submission = os.path.join(tmp, "submission")
            shutil.copytree(solution_dir, os.path.join(submission, "labs", folder))
            common = ["--kit", kit, "--bin", bin_dir, "--self-check", "--labs", lab, "--no-timing", "--quiet",
                      "--diagnose", "off"]
            graded = {}
            both = (("the reference", ["--submission", submission]), ("the starter", []))
            for who, extra in both if os.path.isdir(starter_dir) else both[:1]:
                out = os.path.join(tmp, "out-" + who.split()[-1])
                done = run([tools["gsv-grade"]] + common + extra + ["--out", out])
                report = read_json(os.path.join(out, "report.json"))
                graded[who] = (done, report)
            done, report = graded["the reference"]
            if not report or report["max_score"] <= 0 or report["score"] != report["max_score"]:
                failures.append("the reference does not score full marks against its goldens: render them again "
                                f"(build/bin/gsv-grade --update-goldens --labs {lab}) or see the failing cases above")
                say("3. self-check: the reference " + (f"{report['score']:g} / {report['max_score']:g}" if report else
                                                       "was not graded") + "\n" + tail(done.stdout))
            else:
                say(f"3. self-check: the reference {report['score']:g} / {report['max_score']:g}")
            done, report = graded.get("the starter", (None, None))
            if done is None:
                say("   the starter: none yet (step 1)")
            elif not report or report["score"] != 0:
                failures.append("the starter scores points: each TODO's //@starter code must fail its cases "
                                "(paint kNotDone, or leave out what the TODO writes)")
                say("   the starter " + (f"{report['score']:g} / {report['max_score']:g}" if report else "was not graded")
                    + "\n" + tail(done.stdout))
            else:
                say(f"   the starter 0 / {report['max_score']:g}")

    # 4. The margin bar on every implementation here (and each known mistake failing a case it must fail).
    if rules_only:
        say("4. margins: not run (--rules-only)")
    elif not cases or no_golden:
        say("4. margins: not run (they are shares of the goldens' budgets: render them first)")
    else:
        with tempfile.TemporaryDirectory(prefix="gsv-check-lab-margins-") as work:
            margins = run([tools["gsv-margins"], "--kit", kit, "--bin", bin_dir, "--labs", lab, "--check",
                           "--fail-if-missed", "--work", work])
        if margins.returncode == 0:
            say("4. margins: every case meets the bar on every implementation here")
        elif margins.returncode == 77:
            say("4. margins: no implementation of the margin table here (skipped)")
        else:
            missed.add("margins")
            say("4. margins: missed\n" + tail(margins.stdout, 20))

    # 5. The mistakes per TODO, the held-out ones, the hidden cases; and the cases' count.
    todos = todo_ids(solution_dir)
    per_todo = {todo: 0 for todo in todos}
    if mutants:
        for m in mutants.get("mutants", []) + mutants.get("cpp_mutants", []):
            if m.get("todo") in per_todo:
                per_todo[m["todo"]] += 1
    short = {todo: n for todo, n in per_todo.items() if n < least["mistakes_per_todo"]}
    if not todos:
        failures.append(f"solutions/{folder}/ marks no TODO (//@solution ID ... //@starter ... //@end: labs/README.md)")
    if short or not mutants:
        missed.add("mistakes_per_todo")
    say(f"5. mistakes: " + ", ".join(f"{todo} {n}" for todo, n in sorted(per_todo.items())) +
        f" (tests/mutants/{lab}.json{'' if mutants else ': none'})")
    # The pairs test's stock: GLSL mistakes (a C++ one needs a build of its own) in two different TODOs.
    glsl = {todo: 0 for todo in todos}
    for m in (mutants or {}).get("mutants", []):
        if m.get("todo") in glsl and not m.get("file", "").endswith((".cpp", ".h")):
            glsl[m["todo"]] += 1
    counts = list(glsl.values())
    pairs = sum(counts[i] * counts[j] for i in range(len(counts)) for j in range(i + 1, len(counts)))
    if pairs < least["mistake_pairs"]:
        missed.add("mistake_pairs")
    say(f"   pairs of GLSL mistakes in two TODOs: {pairs}")
    held_out = (read_json(os.path.join(kit, "tests", "heldout", lab + ".json")) or {}).get("mistakes", [])
    if len(held_out) < least["held_out_mistakes"]:
        missed.add("held_out_mistakes")
    say(f"   held out: {len(held_out)} (tests/heldout/{lab}.json)")
    hidden = (read_json(os.path.join(kit, "grader", "hidden", lab + ".json")) or {}).get("cases", [])
    if not hidden:
        missed.add("hidden_cases")
    say(f"   hidden cases: {len(hidden)} (grader/hidden/{lab}.json)")
    if len(cases) < least["public_cases"]:
        missed.add("public_cases")
    say(f"   public cases: {len(cases)} (grader/cases/{lab}.json)")

    say()
    for rule in rules:
        if rule["name"] in missed:
            fill = {"lab": lab, "dir": folder, "least": str(rule.get("least", ""))}
            text = lambda s: re.sub(r"\{(lab|dir|least)\}", lambda m: fill[m.group(1)], s)  # noqa: E731
            say(f"check-lab: {lab} misses the rule '{rule['name']}': {text(rule['says'])}\n    to do: {text(rule['do'])}")
    for failure in failures:
        say(f"check-lab: {lab}: {failure}")
    if missed or failures:
        say(f"check-lab: {lab} is not ready: {len(missed)} rule(s) of tests/lab_rules.json missed, {len(failures)} step(s) failed")
        return 1
    say(f"check-lab: {lab} meets every rule of tests/lab_rules.json")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
