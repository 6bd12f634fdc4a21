#!/usr/bin/env python3
"""A class graded by today's path and by the reusing one, in the same run (scripts/kit bench; grader/README.md).

Six submissions: the starters, the solutions, and four with one lab's TODOs done (labs 02, 04 and 06: GLSL only; lab 05:
C++ too). Each round grades the batch four ways, the first three in an order that turns between rounds:
  today: every lab built, every live reference rendered, a process per case
                                 gsv-grade --batch ... --build-all --fresh-references --one-process-per-case
  reusing: only what differs built, references kept on disk, a process per case
                                 gsv-grade --batch ... --one-process-per-case  (a fresh --grader-cache each round)
  served: the same, and one process per lab renders its cases
                                 gsv-grade --batch ...                         (a fresh --grader-cache each round)
  a rerun with nothing changed   gsv-grade --batch ... --regrade-only changed (into the served run's --out)
and checks that the first three give every submission the same score. Prints seconds per submission, the ratios with
their spread over rounds, and what 300 students would take on one such machine and on 8. A benchmark: it never fails
on speed, only when the grades of the paths differ or a run fails.

usage: bench_class.py BIN_DIR KIT_ROOT [--rounds N] [--workers N] [--quick]
  --quick: public cases only, no timing checks (about a fifth of the time)
"""
import csv
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import kit_labs  # noqa: E402  (the kit's list of labs)

LABS = {lab["id"]: lab["dir"] for lab in kit_labs.labs()}
DONE = {"starter": [], "solutions": list(LABS), "done-lab02": ["lab02"], "done-lab04": ["lab04"],
        "done-lab06": ["lab06"], "done-lab05-cpp": ["lab05"]}


def make_class(kit, folder):
    for name, done in DONE.items():
        labs = os.path.join(folder, name, "labs")
        os.makedirs(labs)
        for lab, lab_dir in LABS.items():
            source = os.path.join(kit, "solutions" if lab in done else "labs", lab_dir)
            if os.path.isdir(source):
                shutil.copytree(source, os.path.join(labs, lab_dir))


def grade(grader, class_dir, out, extra, workers, flags):
    argv = [grader, "--batch", class_dir, "--workers", str(workers), "--seed", "4711", "--out", out] + flags + extra
    start = time.monotonic()
    run = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    seconds = time.monotonic() - start
    if run.returncode != 0:
        sys.exit("bench_class: gsv-grade failed (%s):\n%s" % (" ".join(argv), run.stdout[-3000:]))
    with open(os.path.join(out, "class.csv"), newline="") as f:
        rows = {r["submission"]: r for r in csv.DictReader(f)}
    ungraded = [n for n, r in rows.items() if r["graded"] != "yes"]
    if ungraded:
        sys.exit("bench_class: not graded in %s: %s" % (out, ", ".join(ungraded)))
    return seconds, rows


def main():
    args = sys.argv[1:]
    if len(args) < 2 or args[0] in ("-h", "--help"):
        print(__doc__)
        return 0 if args and args[0] in ("-h", "--help") else 2
    bin_dir, kit = args[0], args[1]
    rounds, workers, quick = 1, 2, False
    rest = args[2:]
    while rest:
        if rest[0] == "--rounds" and len(rest) > 1:
            rounds, rest = int(rest[1]), rest[2:]
        elif rest[0] == "--workers" and len(rest) > 1:
            workers, rest = int(rest[1]), rest[2:]
        elif rest[0] == "--quick":
            quick, rest = True, rest[1:]
        else:
            sys.exit("bench_class: unknown argument '%s' (see --help)" % rest[0])
    grader = os.path.join(bin_dir, "gsv-grade")
    flags = ["--public-only", "--no-timing"] if quick else []
    n = len(DONE)
    work = tempfile.mkdtemp(prefix="gsv-bench-class-")
    try:
        class_dir = os.path.join(work, "class")
        make_class(kit, class_dir)
        per_way = {"today": [], "reuse": [], "served": []}
        rerun = []
        for r in range(rounds):
            cache = {way: os.path.join(work, "cache-%s-%d" % (way, r)) for way in per_way}
            ways = [("today", ["--build-all", "--fresh-references", "--one-process-per-case", "--grader-cache", cache["today"]]),
                    ("reuse", ["--one-process-per-case", "--grader-cache", cache["reuse"]]),
                    ("served", ["--grader-cache", cache["served"]])]
            ways = ways[r % 3:] + ways[:r % 3]
            rows = {}
            for way, extra in ways:
                seconds, rows[way] = grade(grader, class_dir, os.path.join(work, "%s-%d" % (way, r)), extra, workers, flags)
                per_way[way].append(seconds / n)
                print("round %d, %-6s %7.1f s for %d submissions" % (r + 1, way, seconds, n), flush=True)
            for name in DONE:
                scores = {way: rows[way][name]["score"] for way in per_way}
                if len(set(scores.values())) != 1:
                    sys.exit("bench_class: %s scored differently by the paths: %s" % (name, scores))
            seconds, again = grade(grader, class_dir, os.path.join(work, "served-%d" % r),
                                   ["--grader-cache", cache["served"], "--regrade-only", "changed"], workers, flags)
            if any(again[name]["regraded"] != "none" for name in DONE):
                sys.exit("bench_class: a rerun with nothing changed regraded something: %s" %
                         {name: again[name]["regraded"] for name in DONE})
            rerun.append(seconds / n)
            print("round %d, rerun  %7.1f s (nothing changed, nothing regraded)" % (r + 1, seconds), flush=True)

        def spread(values):
            return "%.2f" % statistics.median(values) + ("" if len(values) < 2 else " (%.2f-%.2f)" % (min(values), max(values)))
        print()
        print("grading %d submissions, %d workers, %s, %d round(s), seconds per submission (median, range):" %
              (n, workers, "public cases, no timing" if quick else "hidden cases, timing, live references", rounds))
        today, reuse, served = per_way["today"], per_way["reuse"], per_way["served"]
        print("  today: every lab built, every reference rendered, a process per case  %s" % spread(today))
        print("  reusing: only what differs built, references kept, a process per case %s" % spread(reuse))
        print("  served: reusing, and one process per lab                              %s" % spread(served))
        print("  rerun, nothing changed                                                %s" % spread(rerun))
        print("  reusing / today                                                       %s" % spread([b / a for a, b in zip(today, reuse)]))
        print("  served / today                                                        %s" % spread([b / a for a, b in zip(today, served)]))
        print("  served / reusing                                                      %s" % spread([b / a for a, b in zip(reuse, served)]))
        print("  rerun / first served run                                              %s" % spread([c / b for b, c in zip(served, rerun)]))
        print("  every submission scored the same every way")
        for way, per in (("today's path", statistics.median(today)), ("the reusing path", statistics.median(reuse)),
                         ("the served path", statistics.median(served))):
            class_s = 300 * per
            print("  300 students by %-17s %5.1f h on this machine, %5.1f h on 8 such (shards)" % (way + ":", class_s / 3600, class_s / 3600 / 8))
        print("  (a class's submissions reuse one another's builds and references more than these six do)")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
