#!/usr/bin/env python3
"""The CI templates in grader/ci/ hold together: each YAML parses, its jobs' needs and stages name jobs and stages
that exist, every gsv-grade command they (and the Slurm script) run uses only options and commands that
`gsv-grade --help` lists, the Classroom workflow wires each lab's points to the reporter, and the Slurm script,
run with a stand-in sbatch that runs each job at once, grades a small class into a merged class.csv.

    check_ci_files.py KIT_ROOT BIN_DIR        exit 0: pass, 1: fail, 77: python3-yaml is not installed
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

try:
    import yaml
except ImportError:
    print("check_ci_files: python3-yaml is not installed: skipped")
    sys.exit(77)

kit, bin_dir = map(pathlib.Path, sys.argv[1:3])
ci = kit / "grader" / "ci"
grade = bin_dir / "gsv-grade"
problems = []
help_text = subprocess.run([grade, "--help"], capture_output=True, text=True, check=True).stdout
known_options = set(re.findall(r"(?<![\w-])(--[a-z][a-z-]*)", help_text))
known_commands = set(re.findall(r"gsv-grade ([a-z]+) ", help_text))


def gsv_grade_commands(text):
    """Each gsv-grade command (continuation lines joined) in a shell text: build/bin/gsv-grade or '$grade'."""
    lines = text.replace("\\\n", " ").splitlines()
    found = [re.search(r"(?:bin/gsv-grade|'\$grade')\s+\S.*", line) for line in lines]
    return [m.group(0) for m in found if m]


def check_commands(source, text, required=True):
    commands = gsv_grade_commands(text)
    if required and not commands:
        problems.append(f"{source}: runs no gsv-grade command")
    for command in commands:
        words = command.split()
        if len(words) > 1 and re.fullmatch(r"[a-z]+", words[1]) and words[1] not in known_commands:
            problems.append(f"{source}: 'gsv-grade {words[1]}' is not a gsv-grade command ({command})")
        for option in re.findall(r"(?<![\w-])(--[a-z][a-z-]*)", command):
            if option not in known_options:
                problems.append(f"{source}: gsv-grade has no option {option} ({command.strip()[:100]})")


def shell_of(node):
    """Every string under a YAML node: run blocks, scripts, anchors."""
    if isinstance(node, str):
        return [node]
    if isinstance(node, list):
        return [s for item in node for s in shell_of(item)]
    if isinstance(node, dict):
        return [s for value in node.values() for s in shell_of(value)]
    return []


def check_github(path):
    doc = yaml.safe_load(path.read_text())
    jobs = doc.get("jobs") or {}
    if not jobs:
        problems.append(f"{path.name}: no jobs")
    for name, job in jobs.items():
        needs = job.get("needs", [])
        for need in [needs] if isinstance(needs, str) else needs:
            if need not in jobs:
                problems.append(f"{path.name}: job {name} needs {need}, which does not exist")
        if "runs-on" not in job or not job.get("steps"):
            problems.append(f"{path.name}: job {name} has no runs-on or steps")
        for step in job.get("steps", []):
            if ("uses" in step) == ("run" in step):
                problems.append(f"{path.name}: a step of {name} has both or neither of uses and run: {step}")
    return doc


def check_gitlab(path):
    doc = yaml.safe_load(path.read_text())
    stages = doc.get("stages", [])
    jobs = {k: v for k, v in doc.items() if isinstance(v, dict) and "script" in v}
    for name, job in jobs.items():
        if job.get("stage") not in stages:
            problems.append(f"{path.name}: job {name} is in stage {job.get('stage')}, not one of {stages}")
        for need in job.get("needs", []):
            need = need["job"] if isinstance(need, dict) else need
            if need not in jobs:
                problems.append(f"{path.name}: job {name} needs {need}, which does not exist")
    shards = [s for entry in jobs["grade"]["parallel"]["matrix"] for s in entry["SHARD"]]
    counts = {s.split("/")[1] for s in shards}
    if len(counts) != 1 or sorted(int(s.split("/")[0]) for s in shards) != list(range(1, int(counts.pop()) + 1)):
        problems.append(f"{path.name}: the grade matrix's shards {shards} are not 1/N..N/N")
    return doc


for path in sorted(ci.glob("*.yml")):
    doc = check_gitlab(path) if path.name.startswith("gitlab") else check_github(path)
    # The Classroom workflow grades through scripts/kit; the Pages workflow builds a site and grades nothing.
    check_commands(path.name, "\n".join(shell_of(doc)), required=path.name not in ("github-classroom.yml", "github-pages.yml"))
slurm = ci / "slurm-grade.sh"
check_commands(slurm.name, slurm.read_text())

# Classroom: the reporter's runners and each runner's results come from the points step, which names every lab with a
# case file; the workflow names none (a lab added gives its points unedited).
classroom = yaml.safe_load((ci / "github-classroom.yml").read_text())
steps = classroom["jobs"]["self-check"]["steps"]
reporter = [s for s in steps if "autograding-grading-reporter" in s.get("uses", "")]
labs = sorted(p.stem for p in (kit / "grader" / "cases").glob("lab*.json"))
if len(reporter) != 1:
    problems.append("github-classroom.yml: no autograding-grading-reporter step")
elif reporter[0]["with"]["runners"] != "${{ steps.points.outputs.runners }}":
    problems.append(f"github-classroom.yml: the reporter's runners are {reporter[0]['with']['runners']}, not the points step's")
if re.search(r"\blab[0-9][0-9]\b", (ci / "github-classroom.yml").read_text()):
    problems.append("github-classroom.yml names a lab: the points step gives the labs (every lab with a case file)")
# The points step, run as GitHub runs it on a results.json with no checks: every lab a runner, each with its results
# in the reporter's environment, worth 0 of its public points.
with tempfile.TemporaryDirectory() as tmp:
    tmp = pathlib.Path(tmp)
    (tmp / "output").write_text("")
    (tmp / "env").write_text("")
    run = subprocess.run([sys.executable, ci / "classroom_points.py", tmp / "none.json", "--cases-dir", kit / "grader" / "cases"],
                         capture_output=True, text=True,
                         env=dict(os.environ, GITHUB_OUTPUT=str(tmp / "output"), GITHUB_ENV=str(tmp / "env")))
    outputs = dict(line.split("=", 1) for line in (tmp / "output").read_text().splitlines())
    envs = dict(line.split("=", 1) for line in (tmp / "env").read_text().splitlines())
    if run.returncode != 0 or outputs.get("runners", "").split(",") != labs:
        problems.append(f"classroom_points.py: runners {outputs.get('runners')} are not the labs with a case file {labs} ({run.stderr.strip()})")
    for lab in labs:
        if f"{lab.upper()}_RESULTS" not in envs:
            problems.append(f"classroom_points.py: no {lab.upper()}_RESULTS for the reporter's environment")
if classroom["jobs"]["self-check"].get("name") != "Autograding Tests":
    problems.append("github-classroom.yml: the job is not named 'Autograding Tests' (the reporter looks it up by name)")
if not any("actions/cache" in s.get("uses", "") for s in steps):
    problems.append("github-classroom.yml: no build cache")
if not any("grader/ci/classroom_points.py" in s.get("run", "") for s in steps) or not (ci / "classroom_points.py").is_file():
    problems.append("github-classroom.yml: no step runs grader/ci/classroom_points.py")

# The Slurm script end to end, with an sbatch that runs each job at once (array tasks one after another).
with tempfile.TemporaryDirectory() as tmp:
    tmp = pathlib.Path(tmp)
    fake = tmp / "fakebin"
    fake.mkdir()
    (fake / "sbatch").write_text(r'''#!/usr/bin/env bash
set -euo pipefail
array="" wrap="" chdir=.
for a in "$@"; do
  case "$a" in --array=*) array=${a#--array=} ;; --wrap=*) wrap=${a#--wrap=} ;; --chdir=*) chdir=${a#--chdir=} ;; esac
done
if [ -n "$array" ]; then
  for id in $(seq "${array%-*}" "${array#*-}"); do (cd "$chdir" && SLURM_ARRAY_TASK_ID=$id sh -c "$wrap") >&2; done
else
  (cd "$chdir" && sh -c "$wrap") >&2
fi
echo $RANDOM
''')
    (fake / "sbatch").chmod(0o755)
    for name in ("eve", "fay", "gus"):
        (tmp / "class" / name / "nothing").mkdir(parents=True)
    env = dict(os.environ, PATH=f"{fake}:{os.environ['PATH']}", GSVGRADE_SEED="99")
    run = subprocess.run([slurm, tmp / "class", tmp / "out", "2", "1"], env=env, capture_output=True, text=True)
    if run.returncode != 0:
        problems.append(f"slurm-grade.sh failed: {run.stderr[-600:]}")
    else:
        csv = (tmp / "out" / "class" / "class.csv").read_text().splitlines() if (tmp / "out" / "class" / "class.csv").exists() else []
        if [line.split(",")[0] for line in csv[1:]] != ['"eve"', '"fay"', '"gus"']:
            problems.append(f"slurm-grade.sh: the merged class.csv is not eve, fay, gus: {csv}\n{run.stderr[-600:]}")
    bad = subprocess.run([slurm, tmp / "class", tmp / "out2", "0"], env=env, capture_output=True, text=True)
    if bad.returncode != 2 or "SHARDS" not in bad.stderr:
        problems.append(f"slurm-grade.sh with 0 shards: exit {bad.returncode}, {bad.stderr.strip()}")

for p in problems:
    print(f"check_ci_files: {p}")
print("check_ci_files: " + ("FAIL" if problems else f"the templates in {ci} hold together"))
sys.exit(1 if problems else 0)
