#!/usr/bin/env bash
# The `windows` kind of test, in two steps that ctest runs as two tests (tests/CMakeLists.txt):
#   check_windows.sh build KIT_ROOT BUILD   the labs cross-built for 64-bit Windows with Debian's mingw-w64, and the
#                                           students' zip (scripts/windows-build.sh --dir BUILD/windows; the
#                                           libraries from Debian's source packages, fetched into
#                                           BUILD/windows/sources by `scripts/windows-build.sh sources`, CI's set-up)
#   check_windows.sh wine KIT_ROOT BUILD    that build run under Wine on Xvfb (Mesa's llvmpipe through Wine's
#                                           opengl32), in a Wine prefix made afresh:
#     - every DLL the zip's programs import is beside them or Windows' own (checked on the host, before Wine);
#     - the zip unpacked into the prefix's C: drive: every lab's `list` from there, lab 01's `render` (the headless
#       default: a hidden window, said in one line), `compare` (against the zip's golden image) and its window, each started from the zip with nothing else on
#       its path (the DLLs beside the executables are the only C++ runtime in the prefix);
#     - every public case of every lab's solution drawn by `render --backend window` and judged against its golden by
#       the grader's comparator under the case's golden tolerance (gsv-golden-judge: the self-check's verdicts; the
#       self-check itself, gsv-grade, is Linux's);
#     - a screenshot of lab 01's solution in its window, with its panel, and of the whole X screen.
# Pictures and logs land in BUILD/windows-test/. Skipped (exit 77), naming what is missing, without mingw-w64, Wine,
# Xvfb, zip or the fetched sources; with GSV_REQUIRE_WINDOWS=1 (.ci/run, which installs them) that is a failure.
set -euo pipefail
step=${1:-}
case "$step" in
  build|wine) ;;
  *) echo "usage: check_windows.sh build|wine KIT_ROOT BUILD" >&2; exit 2 ;;
esac
root=$(cd "$2" && pwd)
build=$(cd "$3" && pwd)
win=$build/windows
missing=""
command -v x86_64-w64-mingw32-g++-posix >/dev/null || missing+=" mingw-w64"
command -v wine >/dev/null || missing+=" wine"
[ -x /usr/lib/wine/wine64 ] || command -v wine64 >/dev/null || missing+=" wine64"
command -v xvfb-run >/dev/null || missing+=" xvfb"
command -v zip >/dev/null && command -v unzip >/dev/null || missing+=" zip unzip"
for p in glfw3 imgui zlib; do
  [ -d "$win/sources/$p" ] || { missing+=" Debian's source packages (scripts/windows-build.sh sources --dir $win)"; break; }
done
if [ -n "$missing" ]; then
  echo "check_windows: skipped: missing$missing (.ci/run installs and fetches them)"
  [ "${GSV_REQUIRE_WINDOWS:-0}" = 1 ] && { echo "check_windows: GSV_REQUIRE_WINDOWS=1: the windows test must run here"; exit 1; }
  exit 77
fi

if [ "$step" = build ]; then
  start=$(date +%s)
  rm -f "$win/.built"
  "$root/scripts/windows-build.sh" --dir "$win"
  touch "$win/.built"
  echo "check_windows: the Windows build and its zip took $(( $(date +%s) - start )) s"
  exit 0
fi

[ -f "$win/.built" ] || { echo "check_windows: no finished Windows build in $win (the windows_labs_cross_build test makes it)"; exit 1; }
judge=$build/bin/gsv-golden-judge
out=$build/windows-test
rm -rf "$out"
mkdir -p "$out/renders"
start=$(date +%s)
fail() { echo "check_windows: $*"; exit 1; }
export WINEPREFIX=$out/prefix WINEDEBUG=-all WINEARCH=win64 WINEDLLOVERRIDES="mscoree,mshtml="
# The kit's files for the solutions (built in BUILD/windows/kit/bin, not shipped), as Wine names the host's /.
export GSV_ROOT="Z:${root//\//\\}"
mapfile -t labs < <(python3 -c 'import json, sys; print("\n".join(l["id"] for l in json.load(open(sys.argv[1]))["labs"]))' "$build/labs.json")

# Every DLL the zip's programs import is beside them or one every Windows has (opengl32 is loaded by GLFW at run time).
package=$win/package/gsv-windows
for f in "$package"/*.exe "$package"/*.dll; do
  for dll in $(x86_64-w64-mingw32-objdump -p "$f" | awk '/DLL Name:/ {print $3}'); do
    case "${dll,,}" in kernel32.dll|user32.dll|gdi32.dll|shell32.dll|advapi32.dll|msvcrt.dll|opengl32.dll|ole32.dll) continue ;; esac
    [ -f "$package/$dll" ] || fail "$(basename "$f") imports $dll, which is neither in the zip nor part of Windows"
  done
done
echo "the zip's programs import only Windows' own DLLs and the $(ls "$package"/*.dll | wc -l) DLLs beside them"

# One X server and one wineserver for the whole session (a script in a file: Wine must not read its stdin).
cat > "$out/session.sh" <<'SCRIPT'
set -euo pipefail
out=$1 win=$2 judge=$3 root=$4
shift 4
labs=("$@")
fail() { echo "check_windows: $*"; exit 1; }
cd "$out"
wineboot --init >"$out/wineboot.log" 2>&1 || { cat "$out/wineboot.log"; fail "wineboot failed"; }
# The zip into the fresh prefix's C: drive; its labs are started there, with no GSV_ROOT (they find gsv-assets\).
unzip -q "$win/gsv-windows.zip" -d "$WINEPREFIX/drive_c"
zip_dir='C:\gsv-windows'
for lab in "${labs[@]}"; do
  GSV_ROOT= wine "$zip_dir\\$lab.exe" list </dev/null >"$out/$lab-list.log" 2>&1 || { cat "$out/$lab-list.log"; fail "$lab.exe list failed, started from the zip"; }
  first=$("$judge" "$root" "$lab" --sizes | head -1 | cut -d' ' -f1)
  grep -q "$first" "$out/$lab-list.log" || { cat "$out/$lab-list.log"; fail "$lab.exe list does not name its case $first"; }
  echo "$lab.exe list, from the zip: $(wc -l < "$out/$lab-list.log") lines, its cases named"
done
GSV_ROOT= wine "$zip_dir\\lab01.exe" render --case phong --out 'C:\starter-phong.png' </dev/null >"$out/zip-render.log" 2>&1 ||
  { cat "$out/zip-render.log"; fail "lab01.exe render failed, started from the zip"; }
grep -q "drawing headless in a hidden window" "$out/zip-render.log" || { cat "$out/zip-render.log"; fail "render did not say it draws in a hidden window"; }
cp "$WINEPREFIX/drive_c/starter-phong.png" "$out/zip-starter-phong.png"
echo "lab01.exe render --case phong, from the zip: $(grep -c . "$out/zip-render.log") lines, $(identify -format '%wx%h' "$out/zip-starter-phong.png")"
# compare, the Windows student's check of a case: against the golden image in the zip's gsv-assets\ (no solution there).
GSV_ROOT= wine "$zip_dir\\lab01.exe" compare --case phong </dev/null >"$out/zip-compare.log" 2>&1 ||
  { cat "$out/zip-compare.log"; fail "lab01.exe compare failed, started from the zip"; }
grep -q "against golden image grader/golden/lab01/phong.png" "$out/zip-compare.log" && [ -s "$out/lab01-compare-phong.png" ] ||
  { cat "$out/zip-compare.log"; fail "lab01.exe compare did not compare with the zip's golden image"; }
echo "lab01.exe compare --case phong, from the zip: $(grep -m1 -o 'against golden image.*' "$out/zip-compare.log")"
GSV_ROOT= wine "$zip_dir\\lab01.exe" window --screenshot-after 8 --quit-after 12 --out 'C:\starter-window.png' </dev/null >"$out/zip-window.log" 2>&1 ||
  { cat "$out/zip-window.log"; fail "lab01.exe window failed, started from the zip"; }
cp "$WINEPREFIX/drive_c/starter-window-window.png" "$out/zip-starter-window.png"

# Every public case of every solution, against its golden.
for lab in "${labs[@]}"; do
  mkdir -p "$out/renders/$lab"
  while read -r name size; do
    wine "$win/kit/bin/${lab}_solution.exe" render --backend window --case "$name" --size "$size" --frames 1 --warmup 0 \
      --out "$out/renders/$lab/$name.png" </dev/null >"$out/renders/$lab/$name.log" 2>&1 ||
      echo "$lab/$name: render failed: $(tail -1 "$out/renders/$lab/$name.log")"
  done < <("$judge" "$root" "$lab" --sizes)
  "$judge" "$root" "$lab" "$out/renders/$lab" > "$out/renders/$lab/judged.txt" || true  # judged again below
  tail -1 "$out/renders/$lab/judged.txt"
done

# The solution's window with its panel, and the X screen beside it.
wine "$win/kit/bin/lab01_solution.exe" window --screenshot-after 10 --quit-after 30 --out "$out/lab01-window.png" </dev/null >"$out/window.log" 2>&1 &
pid=$!
for i in $(seq 1 300); do [ -s "$out/lab01-window-window.png" ] && break; sleep 0.1; done
sleep 0.5
import -window root "$out/screen.png"
wait $pid || { cat "$out/window.log"; fail "lab01_solution.exe window failed"; }
wineserver -k || true
SCRIPT
xvfb-run -a -s "-screen 0 1280x800x24" bash "$out/session.sh" "$out" "$win" "$judge" "$root" "${labs[@]}" </dev/null

failed=0
for lab in "${labs[@]}"; do
  "$judge" "$root" "$lab" "$out/renders/$lab" >/dev/null || { grep -v ": passed:" "$out/renders/$lab/judged.txt"; failed=1; }
done
[ $failed = 0 ] || fail "a public case drawn under Wine does not match its golden"
non_blank() {
  [ -s "$1" ] || fail "no $1"
  local deviation
  deviation=$(convert "$1" -colorspace Gray -format "%[fx:standard_deviation]" info:)
  awk -v d="$deviation" 'BEGIN { exit !(d > 0.02) }' || fail "$1 is blank (grey standard deviation $deviation)"
}
for shot in lab01-window.png lab01-window-window.png screen.png zip-starter-window.png; do non_blank "$out/$shot"; done
# The panel beside the picture: the window is wider than the picture.
[ "$(identify -format '%w' "$out/lab01-window-window.png")" -gt "$(identify -format '%w' "$out/lab01-window.png")" ] ||
  fail "lab01's window under Wine has no panel beside its picture"
# The starter from the zip paints what is missing magenta (its TODOs undone): the assets it found are the starter's.
magenta=$(convert "$out/zip-starter-phong.png" -fill black +opaque '#ff00ff' -fill white -opaque '#ff00ff' -format '%[fx:mean]' info:)
awk -v m="$magenta" 'BEGIN { exit !(m > 0.05) }' || fail "lab01.exe from the zip did not draw the starter's magenta (share $magenta)"
grep -q "OpenGL" "$out/window.log" || fail "the window's log names no OpenGL context"
echo "check_windows: under Wine: every lab's list and lab 01's render and window from the zip, every public case of every lab matching its golden, lab 01's window with its panel ($(grep -m1 -o 'OpenGL [^,]*' "$out/window.log")); $(( $(date +%s) - start )) s"
