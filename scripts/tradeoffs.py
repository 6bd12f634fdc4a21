#!/usr/bin/env python3
"""What accuracy costs, across the kit: one line per lab from the <lab>-summary.csv each sweep writes (the
cheapest and the most accurate setting, each one's error and time, and the ratios between them).
Every lab of the kit's list (scripts/kit_labs.py) has its line: a lab whose summary is missing is an error naming it,
never a table without it.
Usage: tradeoffs.py [--markdown] DIR   (DIR holds a folder per lab, lab01/ ..., as scripts/sweeps.sh leaves them)"""
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import kit_labs  # noqa: E402  (the kit's list of labs)


def rows(folder):
    """The summaries' rows, lab by lab, and the labs whose summary is missing."""
    found, missing = [], []
    for lab in kit_labs.ids():
        path = os.path.join(folder, lab, lab + "-summary.csv")
        if not os.path.isfile(path):
            missing.append(lab)
            continue
        with open(path, newline="") as f:
            found.extend(csv.DictReader(f))
    return found, missing


COLUMNS = [("lab", "lab"), ("knob", "knob"), ("error", "error measure"),
           ("cheapest", "cheapest setting"), ("cheapest_error", "its error"), ("cheapest_ms", "ms"),
           ("most_accurate", "most accurate setting"), ("accurate_error", "its error"), ("accurate_ms", "ms"),
           ("time_ratio", "x time"), ("error_ratio", "/ error")]


def main(argv):
    markdown = "--markdown" in argv
    args = [a for a in argv if a != "--markdown"]
    if len(args) != 1:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    table, missing = rows(args[0])
    if missing:
        print("tradeoffs: no " + ", ".join(f"{lab}/{lab}-summary.csv" for lab in missing) + " under " + args[0] +
              " (run the sweeps first: scripts/sweeps.sh, run_sweeps; a lab's sweep is in its lab.json)", file=sys.stderr)
        return 1
    heads = [title for _, title in COLUMNS]
    cells = [[r.get(key, "-") for key, _ in COLUMNS] for r in table]
    if markdown:
        # Compact for a slide: a setting is its knob value, with its series value in brackets.
        def short(setting):
            values = [part.split("=", 1)[-1] for part in setting.split(" ")]
            return values[-1] + (" (" + ", ".join(values[:-1]) + ")" if len(values) > 1 else "")
        print("| lab | knob: error | cheapest | error | ms | most accurate | error | ms | x time | / error |")
        print("| --- | --- | --- | ---: | ---: | --- | ---: | ---: | ---: | ---: |")
        for r in table:
            knob = (r["knob"] + ": " + r["error"]).replace("_", "\\_")
            print("| " + " | ".join([r["lab"], knob, short(r["cheapest"]), r["cheapest_error"], r["cheapest_ms"],
                                     short(r["most_accurate"]), r["accurate_error"], r["accurate_ms"], r["time_ratio"],
                                     r["error_ratio"]]) + " |")
        print("\n: Per lab, the cheapest and the most accurate setting of its sweep (the knob's value, the series' in "
              "brackets); x time: the most accurate one's time over the cheapest's; / error: how many times smaller "
              "its error is. Each error is against the reference its lab's sweep names.")
        return 0
    widths = [max(len(h), *(len(line[i]) for line in cells)) for i, h in enumerate(heads)]
    print("  ".join(h.ljust(w) for h, w in zip(heads, widths)))
    for line in cells:
        print("  ".join(c.ljust(w) for c, w in zip(line, widths)))
    print("\nx time: the most accurate setting's median ms over the cheapest's; / error: the cheapest's error over "
          "the most accurate one's. Each error is against the reference its sweep names (build/tradeoffs/labXX/labXX-sweep.md).")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
