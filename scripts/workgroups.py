#!/usr/bin/env python3
"""Lab 05's work-group sizes, the seed's Figure 11, as a share of this device's measured storage bandwidth, by
work-group size and particle count (scripts/kit bench runs it last, after roofline.py has measured the ceilings).

Runs lab05_solution's sweep over local_size at each particle count (the fountain, Euler, as the seed's kernel), each
into OUT_DIR/particles-N/ with its log; a count this device refuses (its storage blocks cannot hold the particles'
origins and their sentinel slots) is said in one line with the lab's reason, and the other counts go on. Then one
table: a row per local size, a column per count; each cell the GPU's million particles a second and, in brackets,
the share of the storage bandwidth they move: particles/s x the bytes a step moves a particle (the lab's own
statement, the sweep's bytes_per_particle_step) over gsv-ceilings' "storage compute" ceiling at its fastest round
(as the roofline takes it), from the same run's ceilings.json. Below it the CPU's rate (the same update in float on
every core), and a second table of the shares of a buffer copy's bandwidth the sweep timed itself
(glCopyBufferSubData for the GPU, memcpy for the CPU): another bandwidth, not the ceiling.

Usage: workgroups.py BIN_DIR OUT_DIR [--particles N,...] [--values L,...] [--ceilings FILE] [--markdown] [SWEEP OPTION...]
           the sweeps (particles 1M, 2M, 4M and 16M; local sizes 1 to 1024), then the table; options it does not know
           go to every sweep (--size 64x64 --frames 1 ...)
       workgroups.py --table OUT_DIR [--ceilings FILE] [--markdown]
           the table of the sweeps already in OUT_DIR (their ceilings: OUT_DIR/ceilings.json unless named)
"""
import csv
import json
import os
import re
import shutil
import statistics
import subprocess
import sys

COUNTS = [1 << 20, 1 << 21, 1 << 22, 1 << 24]
LOCAL_SIZES = "1,2,4,8,16,32,64,128,256,512,1024"
# The seed's gravity kernel, one curve (Euler), two steps of h = 0.05: each point's time is the steps', not the frame's.
# The local sizes go last (--values adds to the values before it, where --size and --frames replace).
SWEEP = ["--size", "256x256", "--frames", "3", "--set", "field=gravity", "--set", "integrator=euler", "--set", "time=0.1",
         "--knob", "local_size"]
EXIT_UNSUPPORTED = 3  # common/app/exit_status.h: what the device cannot do, its reason the last line
CSV_NAME = "lab05-sweep.csv"
REFUSED_NAME = "refused.txt"
STORAGE = "storage compute"


class Bad(Exception):
    """Input that makes no table: one line naming the file and what is wrong."""


def folder_of(out_dir, count):
    return os.path.join(out_dir, f"particles-{count}")


def counts_in(out_dir):
    found = []
    for name in os.listdir(out_dir):
        match = re.fullmatch(r"particles-(\d+)", name)
        if match and os.path.isdir(os.path.join(out_dir, name)):
            found.append(int(match.group(1)))
    return sorted(found)


def run_sweeps(bin_dir, out_dir, counts, local_sizes, ceilings, extra):
    """Each count's sweep; a refused count leaves its reason in refused.txt. Stops at a sweep that fails otherwise."""
    binary = os.path.join(bin_dir, "lab05_solution")
    if not os.access(binary, os.X_OK):
        raise Bad(f"no {binary}: build it first (scripts/kit build; the student edition has no reference solutions)")
    environment = dict(os.environ, GSV_CEILINGS=os.path.abspath(ceilings))
    # Counts of an earlier run would join this run's table.
    for count in counts_in(out_dir):
        shutil.rmtree(folder_of(out_dir, count))
    for count in counts:
        folder = folder_of(out_dir, count)
        os.makedirs(folder)
        command = [binary, "sweep", *SWEEP, *extra, "--values", local_sizes, "--set", f"particles={count}", "--out-dir", folder]
        print(f"workgroups: {count:,} particles: {' '.join(command[1:])}", file=sys.stderr)
        log = os.path.join(folder, "sweep.log")
        with open(log, "w") as f:
            run = subprocess.run(command, stdout=f, stderr=subprocess.STDOUT, env=environment)
        with open(log) as f:
            lines = [line.rstrip("\n") for line in f if line.strip()]
        last = lines[-1] if lines else "(no output)"
        if run.returncode == EXIT_UNSUPPORTED:
            # "lab05: every setting of the sweep was left out; the first: particles=... needs ...": the lab's reason.
            reason = last.split("; the first: ", 1)[-1] if "; the first: " in last else last.split(": ", 1)[-1]
            with open(os.path.join(folder, REFUSED_NAME), "w") as f:
                f.write(reason + "\n")
            print(f"workgroups: {count:,} particles refused by this device: {reason}", file=sys.stderr)
        elif run.returncode != 0:
            raise Bad(f"the sweep at {count:,} particles failed (exit {run.returncode}; {log}): {last}")


def read_ceiling(path):
    """The storage ceiling in bytes/s (the fastest round, as the roofline's bound takes it) and the device's name."""
    try:
        with open(path) as f:
            data = json.load(f)
    except OSError as e:
        raise Bad(f"cannot read {path}: {e.strerror} (scripts/roofline.py or gsv-ceilings measures it)")
    except ValueError as e:
        raise Bad(f"{path}: not JSON: {e}")
    for entry in data.get("ceilings", []) if isinstance(data, dict) else []:
        if entry.get("key") == STORAGE:
            rates = [entry.get("rate"), entry.get("high")]
            if not all(isinstance(r, (int, float)) and r > 0 for r in rates):
                raise Bad(f"{path}: the '{STORAGE}' ceiling has no rate above 0")
            return max(rates), data.get("renderer", "?")
    raise Bad(f"{path}: no '{STORAGE}' ceiling (gsv-ceilings measures it unless --only left it out)")


COLUMNS = ("gpu_Mparticles_s", "cpu_Mparticles_s", "bytes_per_particle_step", "gpu_bandwidth_fraction",
           "cpu_bandwidth_fraction", "limiter")


def number(path, line, row, column):
    text = row[column]
    try:
        return float(text)
    except ValueError:
        raise Bad(f"{path}:{line}: {column} '{text}' is not a number")


def read_sweep(path):
    """{local size: the row's numbers} from one count's sweep."""
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        if not reader.fieldnames or len(reader.fieldnames) < 2 or reader.fieldnames[1] != "local_size":
            raise Bad(f"{path}: not a sweep of local_size (its knob column is "
                      f"'{reader.fieldnames[1] if reader.fieldnames and len(reader.fieldnames) > 1 else ''}')")
        for column in COLUMNS:
            if column not in reader.fieldnames:
                raise Bad(f"{path}: no column {column} (a sweep from before lab 05 stated it: run the sweeps again)")
        rows = {}
        for line, row in enumerate(reader, start=2):
            try:
                size = int(row["local_size"])
            except ValueError:
                raise Bad(f"{path}:{line}: local_size '{row['local_size']}' is not a whole number")
            if size in rows:
                raise Bad(f"{path}:{line}: local_size {size} a second time")
            if not row.get("limiter"):
                # The lab reads the ceilings only where they are its device's: without a roofline, these are not.
                raise Bad(f"{path}:{line}: no roofline: the sweep found no ceilings of its device (run it with "
                          "GSV_CEILINGS naming the ceilings.json of the same run)")
            rows[size] = {column: number(path, line, row, column) for column in COLUMNS if column != "limiter"}
    if not rows:
        raise Bad(f"{path}: no rows (see the sweep.log beside it)")
    return rows


def gather(out_dir):
    """Each count's rows, or its refusal's reason."""
    if not os.path.isdir(out_dir):
        raise Bad(f"no folder {out_dir}")
    counts = counts_in(out_dir)
    if not counts:
        raise Bad(f"{out_dir}: no particles-N/ folders (run the sweeps first: workgroups.py BIN_DIR {out_dir})")
    sweeps, refused = {}, {}
    for count in counts:
        folder = folder_of(out_dir, count)
        if os.path.isfile(os.path.join(folder, REFUSED_NAME)):
            with open(os.path.join(folder, REFUSED_NAME)) as f:
                refused[count] = f.read().strip()
        elif os.path.isfile(os.path.join(folder, CSV_NAME)):
            sweeps[count] = read_sweep(os.path.join(folder, CSV_NAME))
        else:
            raise Bad(f"{folder}: neither {CSV_NAME} nor {REFUSED_NAME} (see its sweep.log)")
    return sweeps, refused


def build_tables(sweeps, refused, ceiling, renderer):
    """The tables as heads, rows and captions, shared by the text and the Markdown."""
    counts = sorted(sweeps)
    sizes = sorted({size for rows in sweeps.values() for size in rows})
    bytes_used = sorted({r["bytes_per_particle_step"] for rows in sweeps.values() for r in rows.values()})

    def rate_cell(count, size):
        r = sweeps[count].get(size)
        if r is None:
            return "-"
        share = r["gpu_Mparticles_s"] * 1e6 * r["bytes_per_particle_step"] / ceiling
        return f"{r['gpu_Mparticles_s']:.3g} ({share:.2g})"

    def copy_cell(count, size):
        r = sweeps[count].get(size)
        return "-" if r is None else f"{r['gpu_bandwidth_fraction']:.2g}"

    def cpu(count, column):
        return statistics.median(r[column] for r in sweeps[count].values())

    heads = ["local size"] + [f"{count:,}" for count in counts]
    speed = [[str(size)] + [rate_cell(c, size) for c in counts] for size in sizes]
    speed.append(["CPU"] + [f"{cpu(c, 'cpu_Mparticles_s'):.3g}" for c in counts])
    copy = [[str(size)] + [copy_cell(c, size) for c in counts] for size in sizes]
    copy.append(["CPU"] + [f"{cpu(c, 'cpu_bandwidth_fraction'):.2g}" for c in counts])
    per_step = " or ".join(f"{b:g}" for b in bytes_used)
    speed_caption = (f"Lab 05's fountain (Euler) on {renderer}: million particles a second by work-group size (rows) "
                     f"and particle count (columns), and in brackets the share of this device's measured storage "
                     f"bandwidth they move: {per_step} bytes a particle step (the lab's statement) over gsv-ceilings' "
                     f"'{STORAGE}' ceiling, {ceiling / 1e9:.3g} GB/s at its fastest round. CPU: the same update in "
                     f"float on every core, no work groups (the median over the rows).")
    copy_caption = ("The same steps as a share of a buffer copy's bandwidth, which the sweep times itself: the GPU's "
                    "against glCopyBufferSubData's, the CPU's against memcpy's (the CPU's bytes are those its update "
                    "moves). Another bandwidth than the storage ceiling above.")
    refusals = [f"{count:,} particles: {reason}" for count, reason in sorted(refused.items())]
    return heads, speed, speed_caption, copy, copy_caption, refusals


def text_table(heads, rows):
    widths = [max(len(h), *(len(r[i]) for r in rows)) for i, h in enumerate(heads)]
    lines = ["  ".join(h.rjust(w) if i else h.ljust(w) for i, (h, w) in enumerate(zip(heads, widths)))]
    for r in rows:
        lines.append("  ".join(c.rjust(w) if i else c.ljust(w) for i, (c, w) in enumerate(zip(r, widths))))
    return "\n".join(lines)


def markdown_table(heads, rows, caption):
    lines = ["| " + " | ".join(heads) + " |", "| --- |" + " ---: |" * (len(heads) - 1)]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(lines) + "\n\n: " + caption


def show(out_dir, ceilings, markdown):
    ceiling, renderer = read_ceiling(ceilings)
    sweeps, refused = gather(out_dir)
    if not sweeps:
        for count, reason in sorted(refused.items()):
            print(f"workgroups: refused: {count:,} particles: {reason}", file=sys.stderr)
        raise Bad(f"{out_dir}: this device refused every particle count: no table")
    heads, speed, speed_caption, copy, copy_caption, refusals = build_tables(sweeps, refused, ceiling, renderer)
    if markdown:
        print(markdown_table(heads, speed, speed_caption))
        print()
        print(markdown_table(heads, copy, copy_caption))
        if refusals:
            print("\nRefused by this device: " + "; ".join(refusals) + ".")
    else:
        print(speed_caption + "\n")
        print(text_table(heads, speed))
        print("\n" + copy_caption + "\n")
        print(text_table(heads, copy))
        for line in refusals:
            print("refused: " + line)


def parse_counts(text):
    try:
        counts = [int(part) for part in text.split(",")]
    except ValueError:
        raise Bad(f"--particles '{text}': whole numbers, comma-separated")
    if not counts or any(c < 1 for c in counts) or len(set(counts)) != len(counts):
        raise Bad(f"--particles '{text}': different counts, each at least 1")
    return counts


def main(argv):
    usage = __doc__.strip().split("Usage: ", 1)[1]
    markdown, ceilings, counts, local_sizes, table_only, rest = False, None, COUNTS, LOCAL_SIZES, False, []
    i = 0
    while i < len(argv):
        a = argv[i]
        if a == "--markdown":
            markdown = True
        elif a == "--table":
            table_only = True
        elif a in ("--ceilings", "--particles", "--values"):
            if i + 1 >= len(argv):
                raise Bad(f"{a} needs a value")
            if a == "--ceilings":
                ceilings = argv[i + 1]
            elif a == "--particles":
                counts = parse_counts(argv[i + 1])
            else:
                local_sizes = argv[i + 1]
            i += 1
        elif a in ("-h", "--help"):
            print(__doc__.strip())
            return 0
        else:
            rest.append(a)
        i += 1
    if table_only:
        if len(rest) != 1:
            print("usage: " + usage, file=sys.stderr)
            return 2
        out_dir = rest[0]
        show(out_dir, ceilings or os.path.join(out_dir, "ceilings.json"), markdown)
        return 0
    if len(rest) < 2 or rest[0].startswith("-") or rest[1].startswith("-"):
        print("usage: " + usage, file=sys.stderr)
        return 2
    bin_dir, out_dir, extra = rest[0], rest[1], rest[2:]
    # The ceilings roofline.py measured in this run, beside bin/ where the labs look for them; kept with the sweeps.
    ceilings = ceilings or os.path.join(os.path.dirname(os.path.abspath(bin_dir)), "ceilings.json")
    read_ceiling(ceilings)
    os.makedirs(out_dir, exist_ok=True)
    if os.path.abspath(ceilings) != os.path.abspath(os.path.join(out_dir, "ceilings.json")):
        shutil.copy(ceilings, os.path.join(out_dir, "ceilings.json"))
    run_sweeps(bin_dir, out_dir, counts, local_sizes, ceilings, extra)
    show(out_dir, os.path.join(out_dir, "ceilings.json"), markdown)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except Bad as e:
        print(f"workgroups: {e}", file=sys.stderr)
        sys.exit(1)
