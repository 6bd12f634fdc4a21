#!/usr/bin/env python3
"""What accuracy costs, across the kit: one line per lab from the <lab>-summary.csv each sweep writes (the
cheapest and the most accurate setting, each one's error and time, and the ratios between them).
Usage: tradeoffs.py [--markdown] DIR   (DIR holds lab01/ ... lab07/, as scripts/sweeps.sh leaves them)"""
import csv
import glob
import os
import sys


def rows(folder):
    found = []
    for path in sorted(glob.glob(os.path.join(folder, "lab0[1-7]", "lab0[1-7]-summary.csv"))):
        with open(path, newline="") as f:
            found.extend(csv.DictReader(f))
    return found


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
    table = rows(args[0])
    if not table:
        print("tradeoffs: no lab0?/lab0?-summary.csv under " + args[0] + " (run the sweeps first)", file=sys.stderr)
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
