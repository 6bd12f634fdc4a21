#!/usr/bin/env bash
# The `web` kind of test, in two steps that ctest runs as two tests (tests/CMakeLists.txt):
#   check_web.sh build KIT_ROOT BUILD   the browser edition built (the web preset's toolchain, in BUILD/web-build/),
#                                       beside the other tests: it compiles and times nothing
#   check_web.sh pages KIT_ROOT BUILD   that build served on 127.0.0.1 and checked in headless Chromium, on Mesa's
#                                       llvmpipe through ANGLE (under Xvfb) and on SwiftShader (check_pages.js says
#                                       what is checked), beside the other tests (first frames are printed, not
#                                       judged). Screenshots of every page land
#                                       in BUILD/web-test/<rasterizer>/.
# The test's build is the shipped one (scripts/kit web, build-web/) at -O1 instead of -O3, compiled and linked: the
# same sources, flags and WebGL calls, without Binaryen's -O3 passes, which took 60-130 s a page to link here (-O1: 8 s);
# they change no arithmetic (no fast-math), and the pictures come from the same GLSL.
# Skipped (exit 77), naming what is missing, without Emscripten, Chromium, Xvfb, Debian's CodeMirror or
# web/node_modules; with GSV_REQUIRE_WEB=1 (.ci/run, which installs them all) that is a failure instead.
# BUILD: the native build, whose gsv-grade and gsv-make-starters the pages' checks use.
set -euo pipefail
step=${1:-}
case "$step" in
  build|pages) ;;
  *) echo "usage: check_web.sh build|pages KIT_ROOT BUILD" >&2; exit 2 ;;
esac
root=$(cd "$2" && pwd)
build=$(cd "$3" && pwd)
missing=""
command -v em++ >/dev/null || missing+=" emscripten"
command -v chromium >/dev/null || missing+=" chromium"
command -v Xvfb >/dev/null || missing+=" xvfb"
command -v node >/dev/null || missing+=" nodejs"
[ -f /usr/share/javascript/codemirror/lib/codemirror.js ] || missing+=" libjs-codemirror"
[ -d "$root/web/node_modules/playwright-core" ] || missing+=" web/node_modules (npm ci --prefix web)"
if [ -n "$missing" ]; then
  echo "check_web: skipped: missing$missing (.ci/run installs them)"
  [ "${GSV_REQUIRE_WEB:-0}" = 1 ] && { echo "check_web: GSV_REQUIRE_WEB=1: the web test must run here"; exit 1; }
  exit 77
fi
web="$build/web-build"
export NODE_PATH=/usr/share/nodejs
cd "$root"

if [ "$step" = build ]; then
  logs="$build/web-build-logs"
  rm -rf "$logs" "$web/.built"
  mkdir -p "$logs"
  start=$(date +%s)
  cmake --preset web -B "$web" -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DCMAKE_C_FLAGS_RELEASE="-O1 -DNDEBUG" \
    >"$logs/configure.log" 2>&1 || { cat "$logs/configure.log"; exit 1; }
  cmake --build "$web" -j2 >"$logs/build.log" 2>&1 || { tail -40 "$logs/build.log"; exit 1; }
  # What the pages step checks for: this build finished (a build that failed halfway leaves no stamp).
  touch "$web/.built"
  echo "check_web: the web build took $(( $(date +%s) - start )) s"
  exit 0
fi

[ -f "$web/.built" ] || { echo "check_web: no finished web build in $web (the web_edition_builds test makes it)"; exit 1; }
out="$build/web-test"
rm -rf "$out"
mkdir -p "$out"

# The decks beside the pages, where the slides test built them (its quick decks), else scripts/kit slides: one gets a
# screenshot with its live lab; a deck built by neither is a page saying how to build it.
slides="$build/slides-test"
[ -f "$slides/index.html" ] || slides="$build/slides"
"$root/scripts/site-slides.sh" "$web/site" "$slides"
"$root/scripts/site-slides.sh" "$web/lecturer" "$slides"

# A free port on 127.0.0.1 for the server, a free display for Xvfb.
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 "$root/scripts/serve.py" "$web" "$port" >"$out/server.log" 2>&1 &
server=$!
display=:$(( 200 + RANDOM % 500 ))
Xvfb "$display" -screen 0 1280x1024x24 -nolisten tcp >"$out/xvfb.log" 2>&1 &
xvfb=$!
trap 'kill $server $xvfb 2>/dev/null || true' EXIT
for _ in $(seq 50); do
  python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/site/index.html')" 2>/dev/null && break
  sleep 0.1
done

status=0
tests_start=$(date +%s)
DISPLAY=$display node "$root/tests/web/check_pages.js" --base "http://127.0.0.1:$port" --out "$out" \
  --rasterizer angle-llvmpipe --kit "$root" --site "$web" --bin "$build/bin" --editor --native || status=1
node "$root/tests/web/check_pages.js" --base "http://127.0.0.1:$port" --out "$out" \
  --rasterizer swiftshader --kit "$root" --site "$web" --bin "$build/bin" || status=1
echo "check_web: the pages' checks took $(( $(date +%s) - tests_start )) s; screenshots in $out"
exit $status
