#!/usr/bin/env python3
"""scripts/workgroups.py, lab 05's work-group table, without a GPU: on hand-made sweeps and ceilings its cells are
each count's M particles/s with the share of the storage ceiling they move at the lab's stated bytes, the CPU's row
and the copy shares; a refused count is named with its reason; bad input is refused in one line. Then its run mode
with a stand-in lab05_solution that refuses the larger counts as the lab does (exit 3, its reason last): one line
each, and the other counts go on into the table.
Usage: check_workgroups.py KIT        exit 0: holds, 1: it does not (each failure a line)"""
import json
import os
import stat
import subprocess
import sys
import tempfile

HEAD = ("integrator,local_size,median_ms,min_ms,rmse,max_diff,steps,gpu_ms_per_step,gpu_Mparticles_s,cpu_Mparticles_s,"
        "bytes_per_particle_step,gpu_bandwidth_fraction,cpu_bandwidth_fraction,work,bound_ms,fraction,limiter,p25_ms,"
        "p75_ms,reference")
REASON = ("particles=4194304 needs a storage buffer of 134250496 bytes (128.03 MiB) for 4195328 origins of 32 bytes, "
          "the sentinel slots included; this GPU allows 134217728 bytes (128.00 MiB)")

# A stand-in for lab05_solution's sweep: writes a sweep's CSV where --out-dir says, at 10 M particles/s a local size
# over 1 (5 at 1); refuses more than 2,000,000 particles as the lab refuses what its storage blocks cannot hold.
STAND_IN = '''#!/usr/bin/env python3
import os, sys
args = sys.argv[1:]
count = int(next(a.split("=", 1)[1] for a in args if a.startswith("particles=")))
out = args[args.index("--out-dir") + 1]
values = [v for i, a in enumerate(args) if a == "--values" for v in args[i + 1].split(",")]
print("lab05: a stand-in, run as: " + " ".join(args) + "; ceilings: " + os.environ.get("GSV_CEILINGS", "none"), file=sys.stderr)
if count > 2000000:
    print("lab05: every setting of the sweep was left out; the first: %s", file=sys.stderr)
    sys.exit(3)
with open(os.path.join(out, "lab05-sweep.csv"), "w") as f:
    f.write("%s\\n")
    for v in values:
        f.write("euler,%%s,1,1,0,0,2,0.1,%%s,40,112,0.5,0.25,work,0.1,0.5,storage compute,1,1,ref\\n" %% (v, 5 if v == "1" else 10))
''' % (REASON, HEAD)


def sweep_row(size, gpu, cpu, copy=0.5, cpu_copy=0.25, limiter="storage compute", nbytes=112):
    return (f"euler,{size},1,1,0,0,2,0.1,{gpu},{cpu},{nbytes},{copy},{cpu_copy},112M storage compute,0.1,0.5,"
            f"{limiter},1,1,ref\n")


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    script = os.path.join(sys.argv[1], "scripts", "workgroups.py")
    failures = []

    def check(condition, what):
        if not condition:
            failures.append(what)

    def run(*args):
        return subprocess.run([sys.executable, script, *args], capture_output=True, text=True)

    def one_line_refusal(result, text, what):
        check(result.returncode == 1 and text in result.stderr and "Traceback" not in result.stderr and
              len(result.stderr.strip().splitlines()) == 1, f"{what}: not refused in one line naming it: "
              f"{result.returncode} {result.stderr.strip()}")

    with tempfile.TemporaryDirectory() as out:
        def write(relative, text):
            path = os.path.join(out, relative)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w") as f:
                f.write(text)
            return path

        # 1e10 bytes/s at its fastest round (the median lower): 50 M particles/s x 112 bytes is 0.56 of it.
        ceilings = {"renderer": "a test device", "ceilings": [
            {"key": "fetch R32F 2D fragment", "rate": 1e9, "low": 1e9, "high": 1e9, "unit": "fetches/s"},
            {"key": "storage compute", "rate": 8e9, "low": 7e9, "high": 1e10, "unit": "bytes/s"}]}
        write("ceilings.json", json.dumps(ceilings))
        write("particles-65536/lab05-sweep.csv", HEAD + "\n" + sweep_row(1, 5, 30) + sweep_row(64, 50, 40) +
              sweep_row(1024, 40, 50))
        write("particles-131072/lab05-sweep.csv", HEAD + "\n" + sweep_row(1, 6, 31, copy=0.0625) + sweep_row(64, 60, 41))
        write("particles-4194304/refused.txt", REASON + "\n")

        plain = run("--table", out)
        check(plain.returncode == 0, f"the table failed: {plain.stderr.strip()}")
        lines = plain.stdout.splitlines()
        table = [line.split("  ") for line in lines]
        table = [[c.strip() for c in row if c.strip()] for row in table]
        check(["local size", "65,536", "131,072"] in table, f"no heads of the counts: {plain.stdout}")
        check(["64", "50 (0.56)", "60 (0.67)"] in table, f"local size 64's cells (50 M/s x 112 B / 1e10 B/s = 0.56): {plain.stdout}")
        check(["1024", "40 (0.45)", "-"] in table, f"a local size one count lacks shows '-': {plain.stdout}")
        check(["CPU", "40", "36"] in table, f"the CPU's row, the median of its rows: {plain.stdout}")
        check(["1", "0.5", "0.062"] in table, f"the copy shares' table: {plain.stdout}")
        check("112 bytes a particle step (the lab's statement)" in plain.stdout and "10 GB/s" in plain.stdout,
              f"the caption names neither the bytes nor the ceiling: {plain.stdout}")
        check(f"refused: 4,194,304 particles: {REASON}" in lines, f"the refused count is not named with its reason: {plain.stdout}")

        md = run("--table", out, "--markdown")
        check(md.returncode == 0, f"the Markdown failed: {md.stderr.strip()}")
        check("| local size | 65,536 | 131,072 |\n| --- | ---: | ---: |\n| 1 | 5 (0.056) | 6 (0.067) |" in md.stdout,
              f"the Markdown table: {md.stdout}")
        check(f"Refused by this device: 4,194,304 particles: {REASON}." in md.stdout, f"the Markdown's refusal: {md.stdout}")

        # Bad input: one line naming the file.
        sweep = os.path.join(out, "particles-131072", "lab05-sweep.csv")
        write("particles-131072/lab05-sweep.csv", HEAD.replace("bytes_per_particle_step,", "") + "\n")
        one_line_refusal(run("--table", out), f"{sweep}: no column bytes_per_particle_step", "a sweep without the lab's bytes")
        write("particles-131072/lab05-sweep.csv", HEAD + "\n" + sweep_row(1, "fast", 31))
        one_line_refusal(run("--table", out), f"{sweep}:2: gpu_Mparticles_s 'fast' is not a number", "a rate that is no number")
        write("particles-131072/lab05-sweep.csv", HEAD + "\n" + sweep_row(1, 6, 31, limiter=""))
        one_line_refusal(run("--table", out), f"{sweep}:2: no roofline", "a sweep that found no ceilings of its device")
        write("particles-131072/lab05-sweep.csv", HEAD.replace(",local_size,", ",time_step,") + "\n")
        one_line_refusal(run("--table", out), f"{sweep}: not a sweep of local_size", "a sweep of another knob")
        write("particles-131072/lab05-sweep.csv", HEAD + "\n")
        one_line_refusal(run("--table", out), f"{sweep}: no rows", "a sweep of no rows")
        write("particles-131072/lab05-sweep.csv", HEAD + "\n" + sweep_row(1, 6, 31))
        ceilings["ceilings"].pop()
        write("ceilings.json", json.dumps(ceilings))
        one_line_refusal(run("--table", out), "ceilings.json: no 'storage compute' ceiling", "ceilings without the storage one")

    with tempfile.TemporaryDirectory() as root:
        bin_dir, out = os.path.join(root, "bin"), os.path.join(root, "bench")
        os.makedirs(bin_dir)
        stand_in = os.path.join(bin_dir, "lab05_solution")
        with open(stand_in, "w") as f:
            f.write(STAND_IN)
        os.chmod(stand_in, os.stat(stand_in).st_mode | stat.S_IXUSR)
        with open(os.path.join(root, "ceilings.json"), "w") as f:
            json.dump({"renderer": "a test device", "ceilings": [
                {"key": "storage compute", "rate": 1e10, "low": 1e10, "high": 1e10, "unit": "bytes/s"}]}, f)
        # A folder of an earlier run's count, which this run's table must not take in.
        os.makedirs(os.path.join(out, "particles-999"))
        bench = run(bin_dir, out, "--particles", "1048576,4194304,16777216", "--values", "1,64", "--size", "64x64")
        check(bench.returncode == 0, f"the bench stopped at a refused count: {bench.returncode} {bench.stderr.strip()}")
        refusals = [line for line in bench.stderr.splitlines() if "refused by this device" in line]
        check(len(refusals) == 2 and f"workgroups: 4,194,304 particles refused by this device: {REASON}" in refusals,
              f"each refused count is not one line with the lab's reason: {bench.stderr.strip()}")
        check(["64", "10 (0.11)"] in [[c.strip() for c in line.split("  ") if c.strip()] for line in bench.stdout.splitlines()],
              f"the count that ran is not in the table: {bench.stdout}")
        check("999" not in bench.stdout and not os.path.exists(os.path.join(out, "particles-999")),
              "an earlier run's count stayed in the table")
        check(os.path.isfile(os.path.join(out, "ceilings.json")), "the run's ceilings are not kept beside its sweeps")
        # Each sweep gets the options passed on, the local sizes once, its count, and the run's ceilings.
        log = os.path.join(out, "particles-1048576", "sweep.log")
        text = open(log).read() if os.path.isfile(log) else ""
        check("--size 64x64" in text and text.count("--values") == 1 and "--values 1,64 --set particles=1048576" in text and
              "ceilings: " + os.path.join(root, "ceilings.json") in text, f"the sweep's command line or ceilings: {text}")

    for failure in failures:
        print("check_workgroups: " + failure)
    print(f"check_workgroups: {'FAILED' if failures else 'passed'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
