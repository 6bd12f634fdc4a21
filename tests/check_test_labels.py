#!/usr/bin/env python3
"""Every ctest entry carries exactly one kind of test as a label, and README.md documents each kind with the
command that runs it (`scripts/kit test --kind <kind>`). Reads the entries as ctest itself sees them
(`ctest --show-only=json-v1`), so Catch tests discovered after the build are counted too.
Usage: check_test_labels.py BUILD_DIR README KIND..."""
import json
import subprocess
import sys


def main():
    if len(sys.argv) < 4:
        print(__doc__, file=sys.stderr)
        return 2
    build, readme, kinds = sys.argv[1], sys.argv[2], sys.argv[3:]
    listing = subprocess.run(["ctest", "--show-only=json-v1"], cwd=build, capture_output=True, text=True)
    if listing.returncode != 0:
        print("check_test_labels: ctest --show-only failed: " + listing.stderr.strip(), file=sys.stderr)
        return 1
    tests = json.loads(listing.stdout)["tests"]
    problems = []
    count = {kind: 0 for kind in kinds}
    for test in tests:
        labels = next((p["value"] for p in test.get("properties", []) if p["name"] == "LABELS"), [])
        theirs = [label for label in labels if label in kinds]
        if len(theirs) != 1:
            problems.append("%s: labels %s, want exactly one of %s" % (test["name"], labels or "none", ", ".join(kinds)))
        else:
            count[theirs[0]] += 1
    text = open(readme, encoding="utf-8").read()
    for kind in kinds:
        if "scripts/kit test --kind " + kind not in text:
            problems.append("README.md does not say how to run the '%s' tests (scripts/kit test --kind %s)" % (kind, kind))
    for problem in problems:
        print("check_test_labels: " + problem)
    print("check_test_labels: %d tests: %s" % (len(tests), ", ".join("%s %d" % (k, n) for k, n in count.items())))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
