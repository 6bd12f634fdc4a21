#!/usr/bin/env python3
"""The kit promises CMake 3.22 (Ubuntu 22.04's). A 3.22 cannot be installed on the development machine, so this
checks the kit's CMake code and presets against CMake's documented release notes instead:
  1. every cmake_minimum_required names 3.22 or lower, CMakePresets.json is version 3 or lower and asks for
     at most 3.22;
  2. every field of CMakePresets.json is one that presets version 3 defines (a list of what is allowed, so a
     field added later is caught whether or not it is listed below), and no macro of a later version;
  3. no command, keyword, generator expression or variable from the list below, each added after 3.22.
  4. with --configure CMAKE SCRATCH: the running CMake reads the presets (cmake --list-presets) and configures the
     kit into SCRATCH with developer warnings on; a "Policy CMP.... is not set" or any other warning fails. With
     cmake_minimum_required(VERSION 3.22) every policy introduced after 3.22 is unset, so code that depends on a
     later behaviour warns here.
What it cannot prove: that 3.22 configures the kit. A later feature missing from the list in 3 passes, and so
does a behaviour (not a name) that changed after 3.22. The newer CMake that runs the tests keeps every policy
introduced after 3.22 at OLD because of cmake_minimum_required(VERSION 3.22), which covers most of the rest.
Usage: check_cmake_3_22.py KIT_ROOT [--configure CMAKE SCRATCH]"""
import json
import pathlib
import re
import shutil
import subprocess
import sys

OLDEST = (3, 22)
# (what, the version that added it, a regex on CMake code with comments removed)
LATER_FEATURES = [
    ("target_sources(FILE_SET)", "3.23", r"\bFILE_SET\b"),
    ("define_property(INITIALIZE_FROM_VARIABLE)", "3.23", r"\bINITIALIZE_FROM_VARIABLE\b"),
    ("find_package(GLOBAL)", "3.24", r"\bfind_package\s*\([^)]*\bGLOBAL\b"),
    ("$<LINK_LIBRARY>, $<LINK_GROUP>", "3.24", r"\$<LINK_(LIBRARY|GROUP):"),
    ("$<PATH:...>, $<PATH_EQUAL:...>", "3.24", r"\$<PATH(_EQUAL)?:"),
    ("if(PATH_EQUAL)", "3.24", r"\bPATH_EQUAL\b"),
    ("cmake_language(GET_MESSAGE_LOG_LEVEL | SET_DEPENDENCY_PROVIDER)", "3.24",
     r"\bcmake_language\s*\(\s*(GET_MESSAGE_LOG_LEVEL|SET_DEPENDENCY_PROVIDER)"),
    ("CMAKE_COMPILE_WARNING_AS_ERROR, COMPILE_WARNING_AS_ERROR", "3.24", r"\bCOMPILE_WARNING_AS_ERROR\b"),
    ("FetchContent OVERRIDE_FIND_PACKAGE", "3.24", r"\bOVERRIDE_FIND_PACKAGE\b"),
    ("block() / endblock()", "3.25", r"(^|\s)(end)?block\s*\("),
    ("return(PROPAGATE)", "3.25", r"\breturn\s*\(\s*PROPAGATE\b"),
    ("add_subdirectory(SYSTEM), the SYSTEM target property", "3.25", r"\badd_subdirectory\s*\([^)]*\bSYSTEM\b|\bPROPERTIES\b[^)]*\bSYSTEM\b"),
    ("find_*(VALIDATOR)", "3.25", r"\bVALIDATOR\b"),
    ("try_compile/try_run(SOURCE_FROM_CONTENT | SOURCE_FROM_VAR | SOURCE_FROM_FILE)", "3.25", r"\bSOURCE_FROM_(CONTENT|VAR|FILE)\b"),
    ("$<BUILD_LOCAL_INTERFACE>", "3.26", r"\$<BUILD_LOCAL_INTERFACE:"),
    ("$<LIST:...>", "3.27", r"\$<LIST:"),
    ("$<COMPILE_ONLY>", "3.27", r"\$<COMPILE_ONLY:"),
    ("cmake_file_api()", "3.27", r"\bcmake_file_api\s*\("),
    ("add_custom_command(DEPENDS_EXPLICIT_ONLY)", "3.27", r"\bDEPENDS_EXPLICIT_ONLY\b"),
    ("$<TARGET_RUNTIME_DLL_DIRS>, $<TARGET_IMPORT_FILE>", "3.27", r"\$<TARGET_(RUNTIME_DLL_DIRS|IMPORT_FILE)"),
    ("add_custom_command/target(JOB_SERVER_AWARE)", "3.28", r"\bJOB_SERVER_AWARE\b"),
    ("CXX_MODULES file sets", "3.28", r"\bCXX_MODULES\b"),
    ("if(IS_READABLE | IS_WRITABLE | IS_EXECUTABLE)", "3.29", r"\bIS_(READABLE|WRITABLE|EXECUTABLE)\b"),
    ("cmake_language(EXIT)", "3.29", r"\bcmake_language\s*\(\s*EXIT\b"),
    ("$<TARGET_INTERMEDIATE_DIR>, $<QUOTE>", "3.30", r"\$<(TARGET_INTERMEDIATE_DIR|QUOTE)\b"),
    ("cmake_pkg_config()", "3.31", r"\bcmake_pkg_config\s*\("),
    ("add_custom_command(CODEGEN)", "3.31", r"\bCODEGEN\b"),
    ("cmake_language(TRACE)", "4.0", r"\bcmake_language\s*\(\s*TRACE\b"),
]
# What presets version 3 (CMake 3.21) defines; later versions add include, trace, $schema, packagePresets,
# workflowPresets, output.testOutputTruncation and outputJUnitFile, among others.
V3_FIELDS = {
    "": {"version", "cmakeMinimumRequired", "vendor", "configurePresets", "buildPresets", "testPresets"},
    "cmakeMinimumRequired": {"major", "minor", "patch"},
    "configurePresets": {"name", "hidden", "inherits", "condition", "vendor", "displayName", "description",
                         "generator", "architecture", "toolset", "toolchainFile", "binaryDir", "installDir",
                         "cmakeExecutable", "cacheVariables", "environment", "warnings", "errors", "debug"},
    "buildPresets": {"name", "hidden", "inherits", "condition", "vendor", "displayName", "description",
                     "environment", "configurePreset", "inheritConfigureEnvironment", "jobs", "targets",
                     "configuration", "cleanFirst", "verbose", "nativeToolOptions"},
    "testPresets": {"name", "hidden", "inherits", "condition", "vendor", "displayName", "description",
                    "environment", "configurePreset", "inheritConfigureEnvironment", "configuration",
                    "overwriteConfigurationFile", "output", "filter", "execution"},
    "testPresets.output": {"shortProgress", "verbosity", "debug", "outputOnFailure", "quiet", "outputLogFile",
                           "labelSummary", "subprojectSummary", "maxPassedTestOutputSize",
                           "maxFailedTestOutputSize", "maxTestNameWidth"},
    "testPresets.filter": {"include", "exclude"},
    "testPresets.execution": {"stopOnFailure", "enableFailover", "jobs", "resourceSpecFile", "testLoad",
                              "showOnly", "repeat", "interactiveDebugging", "scheduleRandom", "timeout",
                              "noTestsAction"},
}
LATER_MACROS = ["${fileDir}", "${pathListSep}"]  # presets versions 4 and 5


def version_tuple(text):
    return tuple(int(part) for part in text.split(".")[:2])


def without_comments(text):
    # Line comments only (the kit uses no bracket comments); a '#' inside a quoted string is kept.
    out = []
    for line in text.splitlines():
        quoted = False
        for i, c in enumerate(line):
            if c == '"' and (i == 0 or line[i - 1] != "\\"):
                quoted = not quoted
            elif c == "#" and not quoted:
                line = line[:i]
                break
        out.append(line)
    return "\n".join(out)


def cmake_files(root):
    skip = {".git"}
    for path in sorted(root.rglob("*")):
        parts = set(path.relative_to(root).parts)
        if parts & skip or any(p.startswith("build") for p in path.relative_to(root).parts):
            continue
        if path.name == "CMakeLists.txt" or path.suffix == ".cmake":
            yield path


def check_presets(path, problems):
    presets = json.loads(path.read_text(encoding="utf-8"))
    if presets.get("version", 99) > 3:
        problems.append("%s: presets version %s; CMake 3.22 reads at most version 3" % (path, presets.get("version")))
    need = presets.get("cmakeMinimumRequired", {})
    if (need.get("major", 0), need.get("minor", 0)) > OLDEST:
        problems.append("%s: cmakeMinimumRequired %d.%d is above 3.22" % (path, need.get("major"), need.get("minor")))

    def walk(node, where):
        allowed = V3_FIELDS.get(where)
        if allowed is None or not isinstance(node, dict):
            return
        for key, value in node.items():
            if key not in allowed:
                problems.append("%s: field '%s' in %s is not in presets version 3" % (path, key, where or "the top level"))
            child = key if where == "" else where + "." + key
            items = value if isinstance(value, list) else [value]
            for item in items:
                walk(item, child)

    walk(presets, "")
    text = path.read_text(encoding="utf-8")
    for macro in LATER_MACROS:
        if macro in text:
            problems.append("%s: macro %s is from a presets version above 3" % (path, macro))


def check_configure(root, cmake, scratch, problems):
    listed = subprocess.run([cmake, "--list-presets"], cwd=root, capture_output=True, text=True)
    if listed.returncode != 0:
        problems.append("cmake --list-presets fails: " + (listed.stderr.strip().splitlines() or ["?"])[0])
    shutil.rmtree(scratch, ignore_errors=True)
    run = subprocess.run([cmake, "-S", str(root), "-B", str(scratch), "-Wdev", "-DGSV_BUILD_TESTS=ON"],
                         capture_output=True, text=True)
    text = run.stdout + run.stderr
    if run.returncode != 0:
        problems.append("configuring the kit fails:\n" + text[-2000:])
    for m in re.finditer(r"^CMake (Warning|Deprecation Warning).*?(?=^\S|\Z)", run.stderr, re.M | re.S):
        problems.append("configuring warns: " + " ".join(m.group(0).split())[:400])
    shutil.rmtree(scratch, ignore_errors=True)


def main():
    args = sys.argv[1:]
    configure = None
    if len(args) == 4 and args[1] == "--configure":
        configure = args[2:]
        args = args[:1]
    if len(args) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    root = pathlib.Path(args[0]).resolve()
    problems = []
    files = list(cmake_files(root))
    for path in files:
        code = without_comments(path.read_text(encoding="utf-8"))
        for m in re.finditer(r"cmake_minimum_required\s*\(\s*VERSION\s+([0-9.]+)", code):
            if version_tuple(m.group(1)) > OLDEST:
                problems.append("%s: cmake_minimum_required(VERSION %s) is above 3.22" % (path.relative_to(root), m.group(1)))
        for m in re.finditer(r"cmake_policy\s*\(\s*VERSION\s+([0-9.]+)", code):
            if version_tuple(m.group(1)) > OLDEST:
                problems.append("%s: cmake_policy(VERSION %s) is above 3.22" % (path.relative_to(root), m.group(1)))
        for what, since, pattern in LATER_FEATURES:
            for m in re.finditer(pattern, code, re.M):
                line = code.count("\n", 0, m.end() - 1) + 1
                problems.append("%s:%d: %s needs CMake %s" % (path.relative_to(root), line, what, since))
    check_presets(root / "CMakePresets.json", problems)
    if configure:
        check_configure(root, configure[0], pathlib.Path(configure[1]), problems)
    for problem in problems:
        print("check_cmake_3_22: " + problem)
    print("check_cmake_3_22: %d CMake files and CMakePresets.json checked against %d later features%s, %d problems"
          % (len(files), len(LATER_FEATURES), ", configured with developer warnings" if configure else "", len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
