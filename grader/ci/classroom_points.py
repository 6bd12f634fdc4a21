#!/usr/bin/env python3
"""GitHub Classroom points per lab from the grader's results.json.

    classroom_points.py RESULTS_JSON [LAB[,LAB...]] [--cases-dir grader/cases]

For each lab (default: every lab with a case file in the cases folder, the labs this copy of the kit holds), one
result in the shape classroom-resources/autograding-grading-reporter reads from <LAB>_RESULTS (base64 JSON: version,
status, max_score, tests with name, status, score, message), written to $GITHUB_ENV as `<LAB>_RESULTS=<base64>` (the
reporter's step reads it from its environment) and to $GITHUB_OUTPUT as `<lab>=<base64>`, with `runners=lab01,...`
(the reporter's runners); printed as `<lab> <json>` without GITHUB_OUTPUT. So the workflow names no lab: a lab added to
the kit gives its points without an edit. Points are the grader's,
case by case: partial credit, not all or nothing. A lab with no checks in the results (the build or the grader
failed before it) is an error worth 0 of its public points in grader/cases/<lab>.json, so the maximum a student
sees does not shrink; so is every lab when RESULTS_JSON does not exist (the build failed before grading). Exit 2
with one line when RESULTS_JSON is not JSON or a lab's case file cannot be read.
"""
import base64
import json
import os
import pathlib
import re
import sys


def fail(message):
    print(f"classroom_points: {message}", file=sys.stderr)
    sys.exit(2)


def public_points(cases_dir, lab):
    path = cases_dir / f"{lab}.json"
    try:
        cases = json.loads(path.read_text())["cases"]
    except (OSError, ValueError, KeyError) as e:
        fail(f"cannot read the cases of {lab} from {path}: {e}")
    return sum(float(c.get("points", 0)) for c in cases)


def lab_result(results, lab, cases_dir):
    tests = [t for t in results.get("tests", []) if str(t.get("name", "")).startswith(lab + "/")]
    if not tests:
        why = results.get("output") or "the grader wrote no checks for this lab"
        return {"version": 1, "status": "error", "max_score": public_points(cases_dir, lab),
                "tests": [{"name": f"{lab}: not graded", "status": "error", "score": 0, "message": why, "line_no": 0}]}
    entries = []
    for t in tests:
        passed = t.get("status") == "passed"
        entries.append({"name": t["name"], "status": "pass" if passed else "fail", "score": float(t.get("score") or 0),
                        "message": "" if passed else str(t.get("output", "")).strip()[:2000], "line_no": 0})
    return {"version": 1, "status": "pass" if all(e["status"] == "pass" for e in entries) else "fail",
            "max_score": sum(float(t.get("max_score") or 0) for t in tests), "tests": entries}


def main(argv):
    args = argv[1:]
    cases_dir = pathlib.Path("grader/cases")
    if len(args) >= 2 and args[-2] == "--cases-dir":
        cases_dir = pathlib.Path(args[-1])
        args = args[:-2]
    if len(args) not in (1, 2) or any(a.startswith("--") for a in args):
        fail("usage: classroom_points.py RESULTS_JSON [LAB[,LAB...]] [--cases-dir DIR]")
    if len(args) == 2:
        labs = [lab for lab in args[1].split(",") if lab]
        bad = [lab for lab in labs if not re.fullmatch(r"lab[0-9]{2}", lab)]
        if bad or not labs:
            fail(f"labs must be like lab01, got '{args[1]}'")
    else:
        labs = sorted(p.stem for p in cases_dir.glob("lab*.json") if re.fullmatch(r"lab[0-9]{2}", p.stem))
        if not labs:
            fail(f"no lab's case file (labNN.json) in {cases_dir}")
    path = pathlib.Path(args[0])
    if not path.exists():
        print(f"classroom_points: no {path}: the build or the grader failed before grading; 0 points", file=sys.stderr)
        results = {"output": f"no {path}: the build or the grader failed before grading (see the self-check step)"}
    else:
        try:
            results = json.loads(path.read_text())
        except (OSError, ValueError) as e:
            fail(f"cannot read {path}: {e}")
    lines = []
    for lab in labs:
        payload = json.dumps(lab_result(results, lab, cases_dir))
        lines.append((lab, payload, base64.b64encode(payload.encode()).decode()))
    out = os.environ.get("GITHUB_OUTPUT")
    if out:
        with open(out, "a") as f:
            for lab, _, encoded in lines:
                f.write(f"{lab}={encoded}\n")
            f.write("runners=" + ",".join(lab for lab, _, _ in lines) + "\n")
    env = os.environ.get("GITHUB_ENV")
    if env:
        with open(env, "a") as f:
            for lab, _, encoded in lines:
                f.write(f"{lab.upper()}_RESULTS={encoded}\n")
    for lab, payload, _ in lines:
        r = json.loads(payload)
        print(f"{lab}: {sum(t['score'] for t in r['tests']):g} / {r['max_score']:g} ({r['status']})" if out else f"{lab} {payload}")


if __name__ == "__main__":
    main(sys.argv)
