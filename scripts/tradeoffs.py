#!/usr/bin/env python3
"""What accuracy costs, across the kit: one line per lab from the <lab>-summary.csv each sweep writes (the
cheapest and the most accurate setting, each one's error and time, and the ratios between them), and where this
device's ceilings were measured (gsv-ceilings) each one's share of the bound they set, with what sets it; "-" where
they were not, or the lab states no work.
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
            for line, row in enumerate(csv.DictReader(f), start=2):
                for key in ("cheapest_fraction", "accurate_fraction"):
                    if not is_fraction(row.get(key) or ""):
                        sys.exit(f"tradeoffs: {path}:{line}: {key} '{row[key]}' is not a fraction (a number, "
                                 "'<=' before it where the work is an upper bound, or empty)")
                found.append(row)
    return found, missing


def is_fraction(cell):
    try:
        return not cell or float(cell[2:] if cell.startswith("<=") else cell) >= 0
    except ValueError:
        return False


COLUMNS = [("lab", "lab"), ("knob", "knob"), ("error", "error measure"),
           ("cheapest", "cheapest setting"), ("cheapest_error", "its error"), ("cheapest_ms", "ms"),
           ("cheapest_fraction", "of bound"), ("cheapest_limiter", "limited by"),
           ("most_accurate", "most accurate setting"), ("accurate_error", "its error"), ("accurate_ms", "ms"),
           ("accurate_fraction", "of bound"), ("accurate_limiter", "limited by"),
           ("time_ratio", "x time"), ("error_ratio", "/ error")]


def percent(cell):
    """A summary's fraction of the bound as a percentage: "0.2779" is "28%", "<=0.2149" (the work is the most the
    frame can do) "<=21%"; "-" where there is none."""
    if not cell:
        return "-"
    mark = "<=" if cell.startswith("<=") else ""
    return f"{mark}{100 * float(cell[len(mark):]):.0f}%"


def cell(row, key):
    value = row.get(key) or ""
    if key.endswith("_fraction"):
        return percent(value)
    return value or "-"


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
    cells = [[cell(r, key) for key, _ in COLUMNS] for r in table]
    if markdown:
        # Compact for a slide: a setting is its knob value, with its series value in brackets.
        def short(setting):
            values = [part.split("=", 1)[-1] for part in setting.split(" ")]
            return values[-1] + (" (" + ", ".join(values[:-1]) + ")" if len(values) > 1 else "")
        # The share of the bound beside the time it is the share of: a slide has no room for more columns (the
        # limiting resource is in the plain table and in each lab's sweep).
        def timed(r, which):
            share = cell(r, which + "_fraction")
            return r[which + "_ms"] + ("" if share == "-" else " (" + share + ")")
        print("| lab | knob: error | cheapest | error | ms (of bound) | most accurate | error | ms (of bound) | x time | / error |")
        print("| --- | --- | --- | ---: | ---: | --- | ---: | ---: | ---: | ---: |")
        for r in table:
            knob = (r["knob"] + ": " + r["error"]).replace("_", "\\_")
            print("| " + " | ".join([r["lab"], knob, short(r["cheapest"]), r["cheapest_error"], timed(r, "cheapest"),
                                     short(r["most_accurate"]), r["accurate_error"], timed(r, "accurate"),
                                     r["time_ratio"], r["error_ratio"]]) + " |")
        print("\n: Per lab, the cheapest and the most accurate setting of its sweep (the knob's value, the series' in "
              "brackets); x time: the most accurate one's time over the cheapest's; / error: how many times smaller "
              "its error is. Each error is against the reference its lab's sweep names. (of bound): the share of the "
              "bound this device's measured ceilings set that the frame reaches (<=: at most, the lab stating the "
              "most its frame can do; none: no ceilings measured, or no work stated).")
        return 0
    widths = [max(len(h), *(len(line[i]) for line in cells)) for i, h in enumerate(heads)]
    print("  ".join(h.ljust(w) for h, w in zip(heads, widths)))
    for line in cells:
        print("  ".join(c.ljust(w) for c, w in zip(line, widths)))
    print("\nx time: the most accurate setting's median ms over the cheapest's; / error: the cheapest's error over "
          "the most accurate one's. Each error is against the reference its sweep names (build/tradeoffs/labXX/labXX-sweep.md).\n"
          "of bound: the share of the bound this device's measured ceilings set (scripts/roofline.py, gsv-ceilings) that "
          "the frame reaches, limited by that resource; <=: at most (the lab states the most its frame can do); "
          "-: no ceilings measured, or the lab states no work.")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
