#!/usr/bin/env python3
"""scripts/tradeoffs.py on hand-made summaries, one a lab of the kit's list: the share of the bound and its limiter
where a sweep measured them ("<=" kept for an upper bound), "-" where it did not or the summary predates them, in the
plain table and the Markdown the kit's deck includes; a missing summary and a malformed share refused in one line.
Usage: check_tradeoffs.py KIT        exit 0: holds, 1: it does not (each failure a line)"""
import os
import subprocess
import sys
import tempfile

HEAD = "lab,knob,error,cheapest,cheapest_error,cheapest_ms,most_accurate,accurate_error,accurate_ms,time_ratio,error_ratio"
ROOFLINE_HEAD = ",cheapest_fraction,cheapest_limiter,accurate_fraction,accurate_limiter"


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    kit = sys.argv[1]
    script = os.path.join(kit, "scripts", "tradeoffs.py")
    sys.path.insert(0, os.path.join(kit, "scripts"))
    import kit_labs
    ids = kit_labs.ids(kit)
    failures = []

    def check(condition, what):
        if not condition:
            failures.append(what)

    def run(*args):
        return subprocess.run([sys.executable, script, *args], capture_output=True, text=True)

    with tempfile.TemporaryDirectory() as folder:
        def write(lab, text):
            os.makedirs(os.path.join(folder, lab), exist_ok=True)
            with open(os.path.join(folder, lab, lab + "-summary.csv"), "w") as f:
                f.write(text)

        # The first lab measured against ceilings (its cheapest end an upper bound), the second with ceilings but
        # no work stated, the others from before the shares were written.
        measured, unstated = ids[0], ids[1]
        write(measured, HEAD + ROOFLINE_HEAD + "\n" + measured +
              ",k,rmse,k=1,0.5,2,k=4,0.125,8,4,4,<=0.4123,texture (fragment),0.75,storage compute\n")
        write(unstated, HEAD + ROOFLINE_HEAD + "\n" + unstated + ",k,rmse,k=1,0.5,2,k=4,0.125,8,4,4,,,,\n")
        for lab in ids[2:]:
            write(lab, HEAD + "\n" + lab + ",k,rmse,k=1,0.5,2,k=4,0.125,8,4,4\n")

        plain = run(folder)
        check(plain.returncode == 0, f"plain table failed: {plain.stderr.strip()}")
        lines = plain.stdout.splitlines()
        head = lines[0].split()
        check("bound" in head and "limited" in head, f"no share of the bound in the heads: {lines[0]}")
        row = next((line for line in lines if line.startswith(measured + " ")), "")
        check("<=41%" in row and "texture (fragment)" in row and "75%" in row and "storage compute" in row,
              f"{measured}'s row lacks its shares and limiters: {row}")
        for lab in ids[1:]:
            row = next((line for line in lines if line.startswith(lab + " ")), "")
            check(row.split().count("-") == 4, f"{lab}'s row should show '-' for both shares and limiters: {row}")

        md = run("--markdown", folder)
        check(md.returncode == 0, f"markdown failed: {md.stderr.strip()}")
        md_lines = md.stdout.splitlines()
        check(md_lines[0] == "| lab | knob: error | cheapest | error | ms (of bound) | most accurate | error "
                             "| ms (of bound) | x time | / error |", f"Markdown head: {md_lines[0]}")
        check(md_lines[1].count("|") == md_lines[0].count("|"), "the Markdown separator has another number of columns")
        cells = next((line for line in md_lines if line.startswith("| " + measured + " |")), "").split(" | ")
        check(len(cells) == 10 and cells[4] == "2 (<=41%)" and cells[7] == "8 (75%)", f"{measured}'s Markdown row: {cells}")
        cells = next((line for line in md_lines if line.startswith("| " + unstated + " |")), "").split(" | ")
        check(len(cells) == 10 and cells[4] == "2" and cells[7] == "8", f"{unstated}'s Markdown row: {cells}")

        # A share that is no number is named with its file and line.
        write(unstated, HEAD + ROOFLINE_HEAD + "\n" + unstated + ",k,rmse,k=1,0.5,2,k=4,0.125,8,4,4,most,x,,\n")
        bad = run(folder)
        path = os.path.join(folder, unstated, unstated + "-summary.csv")
        check(bad.returncode != 0 and f"{path}:2: cheapest_fraction 'most'" in bad.stderr and "Traceback" not in bad.stderr,
              f"a malformed share was not refused in one line: {bad.returncode} {bad.stderr.strip()}")

        # A missing summary is still an error naming it, never a table without it.
        os.remove(path)
        missing = run(folder)
        check(missing.returncode == 1 and f"{unstated}/{unstated}-summary.csv" in missing.stderr,
              f"a missing summary was not refused: {missing.returncode} {missing.stderr.strip()}")

    for failure in failures:
        print("check_tradeoffs: " + failure)
    print(f"check_tradeoffs: {'FAILED' if failures else 'passed'} ({len(ids)} labs' summaries)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
