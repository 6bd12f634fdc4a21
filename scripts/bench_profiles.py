#!/usr/bin/env python3
"""Frame time on OpenGL ES against the desktop core profile, lab by lab (scripts/kit bench).

Each lab's default view is rendered headless on both profiles in interleaved rounds (core, es; then es, core; ...),
one process each, and the ratio es / core is taken per round: the table gives its median and its spread (the
smallest and largest round). The labs run at their lowest ES version, as the grader runs them with --profile es.
Usage: bench_profiles.py BIN_DIR [--rounds N] [--frames N] [--size WxH] [--labs lab01,lab02]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile


def frame_ms(binary, profile, frames, size, folder):
    png = os.path.join(folder, f"{os.path.basename(binary)}-{profile}.png")
    run = subprocess.run([binary, "render", "--profile", profile, "--frames", str(frames), "--warmup", "2",
                          "--size", size, "--out", png], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"bench_profiles: {os.path.basename(binary)} --profile {profile} failed: "
                 f"{(run.stderr or run.stdout).strip().splitlines()[-1]}")
    with open(os.path.splitext(png)[0] + ".json") as f:
        report = json.load(f)
    return report["timing"]["median_ms"], report["gl"]["effective"]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("bin_dir")
    parser.add_argument("--rounds", type=int, default=4)
    parser.add_argument("--frames", type=int, default=10)
    parser.add_argument("--size", default="512x512")
    parser.add_argument("--labs", default="")
    args = parser.parse_args()
    labs = sorted(name[:-len("_solution")] for name in os.listdir(args.bin_dir) if name.endswith("_solution"))
    if args.labs:
        wanted = args.labs.split(",")
        unknown = [lab for lab in wanted if lab not in labs]
        if unknown:
            sys.exit(f"bench_profiles: no {', '.join(unknown)}_solution in {args.bin_dir}")
        labs = wanted
    print(f"frame time, OpenGL ES (the lab's lowest version) against the core profile (4.1, or 4.3 where a lab's lab.json says so): "
          f"{args.rounds} interleaved rounds of {args.frames} frames at {args.size}")
    print(f"{'lab':6} {'ES':4} {'core ms':>8} {'es ms':>8} {'es/core':>8}  spread (rounds)")
    with tempfile.TemporaryDirectory(prefix="gsv-bench-profiles-") as folder:
        for lab in labs:
            binary = os.path.join(args.bin_dir, lab + "_solution")
            core, es, ratios, version = [], [], [], ""
            for r in range(args.rounds):
                order = ("core", "es") if r % 2 == 0 else ("es", "core")
                times = {}
                for profile in order:
                    times[profile], effective = frame_ms(binary, profile, args.frames, args.size, folder)
                    if profile == "es":
                        version = effective
                core.append(times["core"])
                es.append(times["es"])
                ratios.append(times["es"] / times["core"])
            print(f"{lab:6} {version:4} {statistics.median(core):8.2f} {statistics.median(es):8.2f} "
                  f"{statistics.median(ratios):8.2f}  [{min(ratios):.2f}, {max(ratios):.2f}]")


if __name__ == "__main__":
    main()
