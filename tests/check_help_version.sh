#!/usr/bin/env bash
# Every binary in BIN_DIR, and scripts/kit, answers --help and --version with exit status 0 and a non-empty
# first line; --version prints the project's version (CMake's PROJECT_VERSION, passed here as VERSION).
# Usage: check_help_version.sh BIN_DIR KIT_SCRIPT VERSION
set -uo pipefail
bin_dir=$1
kit=$2
version=$3
failed=0
checked=0
check() {
  local program=$1 option=$2 out status first
  out=$("$program" "$option" 2>&1 </dev/null)
  status=$?
  first=$(printf '%s\n' "$out" | head -n 1)
  checked=$((checked + 1))
  if [ "$status" -ne 0 ] || [ -z "${first// /}" ]; then
    echo "check_help_version: $program $option: exit $status, first line '$first'"
    failed=1
  elif [ "$option" = --version ] && [[ "$first" != *" $version" ]]; then
    echo "check_help_version: $program --version: '$first' does not end in the project's version $version"
    failed=1
  fi
}
programs=()
for program in "$bin_dir"/*; do
  [ -f "$program" ] && [ -x "$program" ] && programs+=("$program")
done
if [ ${#programs[@]} -eq 0 ]; then
  echo "check_help_version: no binaries in $bin_dir"
  exit 1
fi
for program in "${programs[@]}" "$kit"; do
  check "$program" --help
  check "$program" --version
done
echo "check_help_version: ${#programs[@]} binaries and scripts/kit, $checked answers checked"
exit $failed
