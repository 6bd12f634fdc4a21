#!/usr/bin/env python3
"""The kit's labs for scripts: the list cmake/lab_list.cmake takes from the kit's folders (solutions/labNN_name/, or
labs/labNN_name/ in the student edition), with each lab's lab.json, as the build has it.

    import kit_labs; kit_labs.labs(KIT_ROOT)   [{"id": "lab01", "dir": "lab01_gooch", "needs_gl": "4.1", "data": [...],
                                                 "window": [...], "sweeps": [...]}, ...]
    kit_labs.py [--kit DIR] [--ids | --dirs | --json | --sweeps primary|all]
        --ids (default) lab01,lab02,...   --dirs a line "lab01 lab01_gooch" each   --json the whole list
        --sweeps a line a sweep, "NAME LAB OPTION..." (scripts/sweeps.sh): each lab's accuracy sweep, or those and its
        deck's too
"""
import json
import os
import shutil
import subprocess
import sys

KIT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def labs(kit=KIT):
    cmake = shutil.which("cmake")
    if not cmake:
        sys.exit("kit_labs: the list of labs is read by CMake (cmake/lab_list.cmake), and there is no cmake here: "
                 "scripts/setup.sh installs it")
    run = subprocess.run([cmake, "-DGSV_KIT=" + os.path.abspath(kit), "-P", os.path.join(KIT, "cmake", "lab_list.cmake")],
                         capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit("kit_labs: cmake/lab_list.cmake failed:\n" + run.stderr.strip())
    return json.loads(run.stdout)["labs"]


def ids(kit=KIT):
    return [lab["id"] for lab in labs(kit)]


def sweeps(kit=KIT, which="primary"):
    """(name, lab, options) of each sweep: every lab's accuracy sweep (named after the lab: its lab.json's options, or
    none), then with which="all" each lab's other sweeps (named <lab>-...), lab by lab."""
    listed = labs(kit)
    out = []
    for lab in listed:
        own = [s for s in lab["sweeps"] if s["name"] == lab["id"]]
        out.append((lab["id"], lab["id"], own[0]["options"] if own else []))
    if which == "all":
        for lab in listed:
            out.extend((s["name"], lab["id"], s["options"]) for s in lab["sweeps"] if s["name"] != lab["id"])
    return out


def main(argv):
    kit = KIT
    if len(argv) >= 2 and argv[0] == "--kit":
        kit, argv = argv[1], argv[2:]
    what = argv[0] if argv else "--ids"
    if what == "--ids" and len(argv) <= 1:
        print(",".join(ids(kit)))
    elif what == "--dirs" and len(argv) == 1:
        for lab in labs(kit):
            print(lab["id"], lab["dir"])
    elif what == "--json" and len(argv) == 1:
        print(json.dumps({"labs": labs(kit)}, indent=1))
    elif what == "--sweeps" and len(argv) == 2 and argv[1] in ("primary", "all"):
        for name, lab, options in sweeps(kit, argv[1]):
            print(" ".join([name, lab] + options))
    else:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
