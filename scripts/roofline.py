#!/usr/bin/env python3
"""Each lab's frame beside what this device allows (issue 44; scripts/kit bench).

First the device's ceilings, measured by gsv-ceilings (one benchmark a resource, interleaved, with their spread) and
written to the build folder, where every lab then finds them; then each lab at a few settings, rendered headless in
interleaved rounds (every setting once a round), each render's JSON holding the lab's stated work per frame
(Lab::frame_work) and its bound on these ceilings. The table: per lab and setting the work, the bound and the resource
that sets it, the measured frame time (median of the rounds, with their range) and the fraction of the bound reached.
A frame measured faster than the work allows at every benchmark's fastest round fails the run: its timing did not
wait for the device, or its work is overstated. Where a lab states the most its frame can do (rays and streamlines
that end early do less), its fraction is marked "<=": at most that, and not checked.
Usage: roofline.py BIN_DIR OUT_DIR [--rounds N] [--frames N] [--size WxH] [--labs lab01,lab02] [--skip-ceilings]
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys

# The settings each lab is measured at: its defaults first, then what changes its work.
SETTINGS = {
    "lab01": [[], ["mesh_resolution=256"]],
    "lab02": [["length=1"], [], ["length=100"], ["step=midpoint"]],
    "lab03": [[], ["storage=volume", "blend=linear"]],
    "lab04": [[], ["mipmaps=on"]],
    "lab05": [[], ["particles=262144"]],
    "lab06": [[], ["compositing=mip"]],
    "lab07": [[], ["degree=8"]],
}


def render(binary, settings, frames, size, png):
    command = [binary, "render", "--frames", str(frames), "--warmup", "1", "--size", size, "--out", png]
    for s in settings:
        command += ["--set", s]
    run = subprocess.run(command, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"roofline: {os.path.basename(binary)} {' '.join(settings)} failed: "
                 f"{(run.stderr or run.stdout).strip().splitlines()[-1]}")
    with open(os.path.splitext(png)[0] + ".json") as f:
        return json.load(f)


def work_cell(report):
    items = report.get("work", {}).get("items", [])
    if not items:
        return "(not stated)"
    def short(x):
        for scale, suffix in ((1e9, "G"), (1e6, "M"), (1e3, "k")):
            if x >= scale:
                return f"{x / scale:.3g}{suffix}"
        return f"{x:.3g}"
    cell = " + ".join(f"{short(i['amount'])} {i['ceiling']}" for i in items)
    return ("<= " if report["work"].get("upper_bound") else "") + cell


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("bin_dir")
    parser.add_argument("out_dir")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--frames", type=int, default=3)
    parser.add_argument("--size", default="512x512")
    parser.add_argument("--labs", default="")
    parser.add_argument("--skip-ceilings", action="store_true", help="use the ceilings measured last (build/ceilings.json)")
    args = parser.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    ceilings_file = os.path.join(os.path.dirname(os.path.abspath(args.bin_dir)), "ceilings.json")
    if not args.skip_ceilings:
        run = subprocess.run([os.path.join(args.bin_dir, "gsv-ceilings"), "--out", ceilings_file])
        if run.returncode != 0:
            sys.exit("roofline: gsv-ceilings failed")
    if not os.path.exists(ceilings_file):
        sys.exit(f"roofline: no {ceilings_file}: run without --skip-ceilings")
    shutil.copy(ceilings_file, os.path.join(args.out_dir, "ceilings.json"))

    labs = [lab for lab in SETTINGS if os.path.exists(os.path.join(args.bin_dir, lab + "_solution"))]
    if args.labs:
        labs = [lab for lab in labs if lab in args.labs.split(",")]
    points = [(lab, i, settings) for lab in labs for i, settings in enumerate(SETTINGS[lab])]
    times = {p[:2]: [] for p in points}
    reports = {}
    for r in range(args.rounds):
        for lab, i, settings in points:
            print(f"roofline: round {r + 1}/{args.rounds}, {lab} {' '.join(settings) or '(defaults)'}", file=sys.stderr)
            png = os.path.join(args.out_dir, f"{lab}-{i}.png")
            report = render(os.path.join(args.bin_dir, lab + "_solution"), settings, args.frames, args.size, png)
            times[(lab, i)].append(report["timing"]["median_ms"])
            reports[(lab, i)] = report

    renderer = next(iter(reports.values()))["gl"]["renderer"] if reports else "?"
    print(f"\nroofline on {renderer} at {args.size}: each frame's work against this device's ceilings "
          f"(ceilings: {ceilings_file}); frame times: the median of {args.rounds} interleaved rounds [slowest, fastest]")
    header = f"{'lab':6} {'settings':28} {'bound ms':>9} {'limited by':22} {'frame ms':>9} {'rounds':>17} {'fraction':>8}  work"
    print(header)
    rows, failed, unmeasured = [], [], []
    for lab, i, settings in points:
        report = reports[(lab, i)]
        measured = statistics.median(times[(lab, i)])
        spread = f"[{max(times[(lab, i)]):.1f}, {min(times[(lab, i)]):.1f}]"
        roof = report.get("roofline")
        name = " ".join(settings) or "(defaults)"
        if roof:
            fraction = roof["bound_ms"] / measured
            upper = roof.get("upper_bound", False)
            if not upper and min(times[(lab, i)]) < roof["bound_ms"]:
                failed.append(f"{lab} {name}: {min(times[(lab, i)]):.3f} ms is faster than the {roof['limiter']} ceiling "
                              f"allows ({roof['bound_ms']:.3f} ms at its fastest)")
            if roof.get("unmeasured"):
                unmeasured.append(f"{lab} {name}: {', '.join(roof['unmeasured'])}")
            cell = ("<=" if upper else "") + f"{100 * fraction:.1f}%"
            print(f"{lab:6} {name:28} {roof['bound_ms']:9.2f} {roof['limiter']:22} {measured:9.2f} {spread:>17} "
                  f"{cell:>8}  {work_cell(report)}")
            rows.append((lab, name, roof["bound_ms"], roof["limiter"], measured, fraction, work_cell(report), upper))
        else:
            print(f"{lab:6} {name:28} {'-':>9} {'-':22} {measured:9.2f} {spread:>17} {'-':>8}  {work_cell(report)}")
            rows.append((lab, name, float("nan"), "", measured, float("nan"), work_cell(report), False))
    for line in unmeasured:
        print(f"no ceiling measured, left out of the bound: {line}")
    csv_path = os.path.join(args.out_dir, "roofline.csv")
    with open(csv_path, "w") as f:
        f.write("lab,settings,bound_ms,limiter,frame_ms,fraction,work,upper_bound\n")
        for row in rows:
            f.write(",".join(str(x).replace(",", ";") for x in row) + "\n")
    print(f"wrote {csv_path}")
    if shutil.which("gnuplot") and rows:
        plot(rows, renderer, args.out_dir)
    if failed:
        for line in failed:
            print("roofline: FAILED: " + line, file=sys.stderr)
        sys.exit(1)


def plot(rows, renderer, out_dir):
    data = os.path.join(out_dir, "roofline.dat")
    with open(data, "w") as f:
        for lab, name, _, limiter, _, fraction, _, upper in rows:
            if fraction == fraction:  # not NaN
                label = ("<=" if upper else "") + f"{100 * fraction:.0f}%"
                f.write(f"\"{lab} {name}\" {100 * fraction:.2f} \"{label}\"\n")
    script = os.path.join(out_dir, "roofline.gp")
    with open(script, "w") as f:
        f.write(f"""set terminal pngcairo size 1200,620 font ",10"
set bmargin 12
set rmargin 12
set output "{os.path.join(out_dir, 'roofline.png')}"
set title "Each lab's frame as a share of this device's ceiling ({renderer.replace('"', '')})\\n<=: the lab states the most its frame can do (streamlines and rays that end early do less)"
set ylabel "% of the bound the ceilings set"
set yrange [0:{max(110, 10 + max((100 * r[5] for r in rows if r[5] == r[5]), default=0)):.0f}]
set style fill solid 0.6
set boxwidth 0.7
set xtics rotate by -35 left
set grid ytics
unset key
set arrow from graph 0, first 100 to graph 1, first 100 nohead dt 2 lc rgb "red"
plot "{data}" using 0:2:xtic(1) with boxes lc rgb "#4477aa", "" using 0:2:3 with labels offset 0,0.7
""")
    subprocess.run(["gnuplot", script])
    print(f"wrote {os.path.join(out_dir, 'roofline.png')}")


if __name__ == "__main__":
    main()
