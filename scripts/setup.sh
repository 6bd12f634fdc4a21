#!/usr/bin/env bash
# Installs what the kit needs to build, run headless, test and plot, where it is missing.
# Debian/Ubuntu: installs with apt-get (through sudo when not root). Elsewhere: prints the equivalents.
# --web: also what the browser edition builds with (scripts/kit web): Emscripten, Debian's CodeMirror, and npm where
# there is no npm yet (the page's JSZip and its tests' playwright-core come from npm: scripts/kit web runs npm ci).
set -euo pipefail

debian_packages=(
  cmake ninja-build g++ pkg-config ccache
  libglfw3-dev libglm-dev catch2 libstb-dev fonts-dejavu-core zlib1g-dev libtinyobjloader-dev
  nlohmann-json3-dev
  libegl-dev libgl-dev libgl1-mesa-dri libegl-mesa0 libosmesa6-dev
  libimgui-dev
  python3-glad glslang-tools python-matplotlib-data python3-nibabel python3-yaml
  xvfb xauth imagemagick gnuplot-nox pandoc
  similarity-tester
)

if [ "${1:-}" = "--web" ]; then
  debian_packages+=(emscripten libjs-codemirror)
  command -v npm >/dev/null 2>&1 || debian_packages+=(npm)
fi

if [ "$(uname -s)" = "Darwin" ]; then
  cat <<'MSG'
macOS: install the kit's dependencies with Homebrew, then build with the same CMake commands:
  brew install cmake ninja glfw glm stb nlohmann-json gnuplot
  (what cmake/dependencies.cmake finds; no grader or tests on macOS, so no Catch2. No EGL or OSMesa either: the labs
  draw in a window, and headless in a hidden one, on an OpenGL 4.1 core context, which every lab runs on: lab 05
  steps its particles by transform feedback there. CI proves the labs at 4.1 by Mesa's version override, not this line)
MSG
  exit 0
fi
case "$(uname -s)" in
  MINGW*|MSYS*|CYGWIN*)
    cat <<'MSG'
Windows: install the dependencies with vcpkg and point CMake at its toolchain file:
  vcpkg install glfw3 glm stb nlohmann-json zlib imgui[glfw-binding,opengl3-binding]
  cmake --preset default -DCMAKE_TOOLCHAIN_FILE=%VCPKG_ROOT%/scripts/buildsystems/vcpkg.cmake
MSG
    exit 0 ;;
esac

if ! command -v dpkg-query >/dev/null 2>&1; then
  echo "setup: not a Debian-based system; install the equivalents of: ${debian_packages[*]}" >&2
  exit 0
fi

missing=()
for p in "${debian_packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#debian_packages[@]} packages present"
  exit 0
fi
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
# An older release (Ubuntu 22.04) lacks a package or two: install what the archive has and name the rest, rather
# than let one unknown name stop the whole set-up.
available=() absent=()
for p in "${missing[@]}"; do
  if apt-cache show "$p" >/dev/null 2>&1; then available+=("$p"); else absent+=("$p"); fi
done
if [ ${#available[@]} -gt 0 ]; then
  echo "setup: installing ${available[*]}"
  $sudo apt-get install -y -qq --no-install-recommends "${available[@]}" >/dev/null
fi
if [ ${#absent[@]} -gt 0 ]; then
  echo "setup: not in this system's package archive, so not installed: ${absent[*]}" >&2
  echo "setup: (libimgui-dev: the window falls back to its title bar; python3-glad, chromium, pandoc, similarity-tester:" >&2
  echo "        their tests are skipped; anything else: the build names what it misses)" >&2
fi
echo "setup: done"
