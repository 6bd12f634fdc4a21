#!/usr/bin/env bash
# The committed GL loader must be exactly what scripts/regen-glad.sh generates (exit 77: glad missing).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
command -v glad >/dev/null || { echo "check_glad: glad not installed (python3-glad); skipped"; exit 77; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$root/scripts/regen-glad.sh" "$tmp"
diff -r "$tmp/include" "$root/third_party/glad/include"
diff -r "$tmp/src" "$root/third_party/glad/src"
echo "glad loader matches its regeneration"
