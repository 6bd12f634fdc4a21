#!/usr/bin/env bash
# The kit's labs for 64-bit Windows, cross-built on Debian with mingw-w64, and the zip a Windows student unpacks and
# runs (README, "On Windows"). The libraries the labs link that Debian has no mingw build of (GLFW, zlib, Dear ImGui) are
# built from Debian's own source packages; glm, nlohmann_json and stb are header-only and taken from Debian's -dev
# packages (libglm-dev, nlohmann-json3-dev, libstb-dev, which scripts/setup.sh installs).
#
#   scripts/windows-build.sh sources [--dir DIR]   fetch Debian's source packages of GLFW, Dear ImGui and zlib into
#                                                   DIR/sources (the only step that uses the network: CI's set-up)
#   scripts/windows-build.sh [build] [--dir DIR]   from DIR/sources: the libraries into DIR/deps (once), the labs
#                                                   (starters and solutions) into DIR/kit, the zip DIR/gsv-windows.zip
#
# DIR defaults to build-win/ in the kit (the instructor's kit or the student edition). The zip holds the starters (labNN.exe), the C++ runtime's DLLs beside them
# (mingw's libstdc++, libgcc and winpthread: a Windows machine has none of them), and in gsv-assets/ what the labs read
# (labs/, shaders/, the data the labs use, the public cases and their golden images); no solution.
# Needs: mingw-w64 (x86_64-w64-mingw32-g++-posix), cmake, ninja, zip; for `sources`, apt-get and network.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
die() { echo "windows-build: $*" >&2; exit 1; }
step=build
dir=$root/build-win
while [ $# -gt 0 ]; do
  case "$1" in
    sources|build) step=$1 ;;
    --dir) [ $# -ge 2 ] || die "--dir needs a folder"; dir=$2; shift ;;
    -h|--help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) die "unknown argument '$1' (expected sources, build or --dir DIR)" ;;
  esac
  shift
done
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
sources=$dir/sources
# Debian 12's (bookworm) packages, whatever Debian this runs on: GLFW 3.3.8, Dear ImGui 1.86, zlib 1.2.13.
packages=(glfw3 imgui zlib)
release=bookworm

if [ "$step" = sources ]; then
  command -v apt-get >/dev/null || die "no apt-get: fetch the source packages of ${packages[*]} from Debian $release by hand into $sources"
  # A private source list and package lists: the system's apt set-up is neither read nor changed.
  apt=$dir/apt
  mkdir -p "$apt/lists/partial" "$apt/cache/archives/partial" "$apt/parts" "$sources"
  echo "deb-src http://deb.debian.org/debian $release main" > "$apt/sources.list"
  apt_options=(-q -o "Dir::Etc::SourceList=$apt/sources.list" -o "Dir::Etc::SourceParts=$apt/parts"
               -o "Dir::State::Lists=$apt/lists" -o "Dir::Cache=$apt/cache" -o Debug::NoLocking=1)
  apt-get "${apt_options[@]}" update >"$apt/update.log" 2>&1 || { cat "$apt/update.log"; die "apt-get update failed"; }
  # Only the upstream tarballs are unpacked (Debian's patches concern Debian's own build).
  (cd "$sources" && apt-get "${apt_options[@]}" source --download-only "${packages[@]}") >"$apt/source.log" 2>&1 ||
    { cat "$apt/source.log"; die "apt-get source failed"; }
  for p in "${packages[@]}"; do
    tarball=$(ls "$sources"/${p}_*.orig.tar.* | head -1)
    rm -rf "${sources:?}/$p" && mkdir -p "$sources/$p"
    tar -xf "$tarball" -C "$sources/$p" --strip-components=1
    echo "windows-build: $(basename "$tarball") unpacked into $sources/$p"
  done
  exit 0
fi

for tool in x86_64-w64-mingw32-g++-posix x86_64-w64-mingw32-gcc-posix x86_64-w64-mingw32-ar cmake ninja zip python3; do
  command -v $tool >/dev/null || die "$tool not installed (mingw-w64, cmake, ninja-build, zip: .ci/run installs them)"
done
for p in "${packages[@]}"; do
  [ -d "$sources/$p" ] || die "no $sources/$p: run 'scripts/windows-build.sh sources --dir $dir' first (it needs the network)"
done
for h in /usr/include/glm/glm.hpp /usr/include/nlohmann/json.hpp /usr/include/stb/stb_image.h; do
  [ -f "$h" ] || die "no $h (libglm-dev, nlohmann-json3-dev, libstb-dev: scripts/setup.sh installs them)"
done
toolchain=$root/cmake/mingw-w64.cmake
deps=$dir/deps
jobs=$(nproc)

# The libraries, once (deps/.built names the sources they came from).
stamp="${packages[*]} $(cd "$sources" && ls ./*.orig.tar.* 2>/dev/null | tr '\n' ' ')"
if [ "$(cat "$deps/.built" 2>/dev/null)" != "$stamp" ]; then
  start=$(date +%s)
  rm -rf "$deps" "$dir/deps-build"
  mkdir -p "$deps/include" "$deps/lib/cmake" "$dir/deps-build"
  logs=$dir/deps-build
  cmake -S "$sources/glfw3" -B "$dir/deps-build/glfw" -G Ninja -DCMAKE_TOOLCHAIN_FILE="$toolchain" \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$deps" -DGLFW_BUILD_EXAMPLES=OFF -DGLFW_BUILD_TESTS=OFF \
    -DGLFW_BUILD_DOCS=OFF >"$logs/glfw.log" 2>&1 &&
    cmake --build "$dir/deps-build/glfw" --target install -j"$jobs" >>"$logs/glfw.log" 2>&1 ||
    { tail -30 "$logs/glfw.log"; die "GLFW did not build (log: $logs/glfw.log)"; }
  # zlib and ImGui: their few sources compiled straight into static libraries (zlib's CMake build wants a Windows
  # resource file Debian's tarball leaves out; ImGui has no build of its own).
  compile() {  # compile OUT_DIR COMPILER FLAGS... -- SOURCES...
    local out=$1 cc=$2; shift 2
    local flags=()
    while [ "$1" != -- ]; do flags+=("$1"); shift; done
    shift
    mkdir -p "$out"
    printf '%s\n' "$@" | xargs -P "$jobs" -I{} sh -c '"$0" "$@" -c {} -o "'"$out"'/$(basename {}).o"' "$cc" "${flags[@]}"
  }
  z=$sources/zlib
  compile "$dir/deps-build/zlib" x86_64-w64-mingw32-gcc-posix -O2 -I"$z" -- \
    "$z"/{adler32,compress,crc32,deflate,gzclose,gzlib,gzread,gzwrite,infback,inffast,inflate,inftrees,trees,uncompr,zutil}.c \
    >"$logs/zlib.log" 2>&1 || { cat "$logs/zlib.log"; die "zlib did not build"; }
  x86_64-w64-mingw32-ar rcs "$deps/lib/libz.a" "$dir/deps-build/zlib"/*.o
  cp "$z/zlib.h" "$deps/include/" && cp "$z/zconf.h.in" "$deps/include/zconf.h"
  i=$sources/imgui
  compile "$dir/deps-build/imgui" x86_64-w64-mingw32-g++-posix -O2 -I"$i" -I"$deps/include" -- \
    "$i"/{imgui,imgui_draw,imgui_tables,imgui_widgets}.cpp "$i"/backends/imgui_impl_{glfw,opengl3}.cpp \
    >"$logs/imgui.log" 2>&1 || { cat "$logs/imgui.log"; die "Dear ImGui did not build"; }
  x86_64-w64-mingw32-ar rcs "$deps/lib/libimgui.a" "$dir/deps-build/imgui"/*.o
  cp "$i"/im*.h "$i"/backends/imgui_impl_{glfw,opengl3}.h "$i"/backends/imgui_impl_opengl3_loader.h "$deps/include/" 2>/dev/null ||
    cp "$i"/im*.h "$i"/backends/imgui_impl_{glfw,opengl3}.h "$deps/include/"
  # ImGui as vcpkg's port presents it (imgui::imgui, the bindings beside imgui.h), which cmake/dependencies.cmake
  # finds first; glm and nlohmann_json by configs of their own, so CMake never looks in the host's /usr.
  mkdir -p "$deps/lib/cmake/imgui" "$deps/lib/cmake/glm" "$deps/lib/cmake/nlohmann_json"
  cat > "$deps/lib/cmake/imgui/imguiConfig.cmake" <<'CONFIG'
# Written by scripts/windows-build.sh: Dear ImGui from Debian's source package with its GLFW and OpenGL 3 bindings.
include(CMakeFindDependencyMacro)
find_dependency(glfw3)
if(NOT TARGET imgui::imgui)
  add_library(imgui::imgui STATIC IMPORTED)
  get_filename_component(_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
  set_target_properties(imgui::imgui PROPERTIES IMPORTED_LOCATION "${_prefix}/lib/libimgui.a"
    INTERFACE_INCLUDE_DIRECTORIES "${_prefix}/include" INTERFACE_LINK_LIBRARIES glfw)
endif()
CONFIG
  cat > "$deps/lib/cmake/glm/glmConfig.cmake" <<'CONFIG'
# Written by scripts/windows-build.sh: Debian's header-only glm, linked into this prefix.
if(NOT TARGET glm::glm)
  add_library(glm::glm INTERFACE IMPORTED)
  set_target_properties(glm::glm PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${CMAKE_CURRENT_LIST_DIR}/../../../include")
endif()
CONFIG
  json_version=$(for part in MAJOR MINOR PATCH; do
    grep -rhm1 "^#define NLOHMANN_JSON_VERSION_$part " /usr/include/nlohmann | awk '{print $3}' | head -1
  done | paste -sd.)
  [[ "$json_version" =~ ^[0-9]+\.[0-9]+\.[0-9]+$ ]] || die "cannot read nlohmann_json's version from /usr/include/nlohmann"
  cat > "$deps/lib/cmake/nlohmann_json/nlohmann_jsonConfig.cmake" <<'CONFIG'
# Written by scripts/windows-build.sh: Debian's header-only nlohmann_json, linked into this prefix.
if(NOT TARGET nlohmann_json::nlohmann_json)
  add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
  set_target_properties(nlohmann_json::nlohmann_json PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${CMAKE_CURRENT_LIST_DIR}/../../../include")
endif()
CONFIG
  cat > "$deps/lib/cmake/nlohmann_json/nlohmann_jsonConfigVersion.cmake" <<CONFIG
set(PACKAGE_VERSION $json_version)
if(PACKAGE_FIND_VERSION VERSION_GREATER PACKAGE_VERSION)
  set(PACKAGE_VERSION_COMPATIBLE FALSE)
else()
  set(PACKAGE_VERSION_COMPATIBLE TRUE)
endif()
CONFIG
  ln -s /usr/include/glm /usr/include/nlohmann /usr/include/stb "$deps/include/"
  echo "$stamp" > "$deps/.built"
  echo "windows-build: GLFW, zlib and Dear ImGui built into $deps in $(( $(date +%s) - start )) s"
fi

# The labs, starters and solutions, with the kit's warnings as errors (the build is warning-free on Windows too).
start=$(date +%s)
kit=$dir/kit
cmake -S "$root" -B "$kit" -G Ninja -DCMAKE_TOOLCHAIN_FILE="$toolchain" -DGSV_WINDOWS_DEPS="$deps" \
  -DCMAKE_BUILD_TYPE=Release -DGSV_WERROR=ON >"$dir/configure.log" 2>&1 || { cat "$dir/configure.log"; die "configure failed"; }
grep -q "ImGui ON" "$dir/configure.log" || { cat "$dir/configure.log"; die "configured without Dear ImGui (no panel)"; }
mapfile -t labs < <(python3 -c 'import json, sys; print("\n".join(l["id"] for l in json.load(open(sys.argv[1]))["labs"]))' "$kit/labs.json")
targets=()
# The solutions where the kit has them (the instructor's: the windows test draws the goldens' cases with them); the
# student edition builds its starters alone.
for lab in "${labs[@]}"; do
  targets+=("$lab")
  [ -d "$root/solutions" ] && targets+=("${lab}_solution")
done
cmake --build "$kit" -j"$jobs" --target "${targets[@]}" >"$dir/build.log" 2>&1 || { grep -B2 -A12 -m3 "error\|FAILED" "$dir/build.log"; die "the labs did not build (log: $dir/build.log)"; }
warnings=$(grep -c "warning:" "$dir/build.log" || true)
[ "$warnings" = 0 ] || { grep -A4 "warning:" "$dir/build.log" | head -40; die "$warnings warnings in the Windows build"; }
echo "windows-build: ${#targets[@]} lab programs built in $kit/bin in $(( $(date +%s) - start )) s, no warning"

# The zip: the starters, the runtime DLLs they import, gsv-assets/ (README, "Shaders and data are found through ...").
package=$dir/package/gsv-windows
rm -rf "$dir/package" "$dir/gsv-windows.zip"
mkdir -p "$package/gsv-assets/grader/golden" "$package/licences"
for lab in "${labs[@]}"; do cp "$kit/bin/$lab.exe" "$package/"; done
for dll in libstdc++-6.dll libgcc_s_seh-1.dll libwinpthread-1.dll; do
  found=$(x86_64-w64-mingw32-g++-posix -print-file-name=$dll)
  [ -f "$found" ] || found=$(ls /usr/lib/gcc/x86_64-w64-mingw32/*-posix/$dll /usr/x86_64-w64-mingw32/lib/$dll 2>/dev/null | head -1)
  [ -f "$found" ] || die "mingw's $dll not found"
  cp "$found" "$package/"
  cp "$found" "$kit/bin/"  # the build's own programs start too (the windows test's solutions)
done
# Without their symbols (mingw's libstdc++ DLL is 23 MB with them, 2 MB without): nothing in the zip is debugged.
x86_64-w64-mingw32-strip --strip-unneeded "$package"/*.exe "$package"/*.dll
cp -r "$root/labs" "$root/shaders" "$root/grader/cases" "$package/gsv-assets/"
mv "$package/gsv-assets/cases" "$package/gsv-assets/grader/cases"
mkdir -p "$package/gsv-assets/data"
for d in $(python3 -c 'import json, sys; print("\n".join(sorted({d for l in json.load(open(sys.argv[1]))["labs"] for d in l["data"]})))' "$kit/labs.json"); do
  cp -r "$root/data/$d" "$package/gsv-assets/data/"
done
for lab in "${labs[@]}"; do
  mkdir -p "$package/gsv-assets/grader/golden/$lab"
  find "$root/grader/golden/$lab" -maxdepth 1 -name '*.png' ! -name 'mistakes.png' -exec cp {} "$package/gsv-assets/grader/golden/$lab/" \;
done

cp "$sources/glfw3/LICENSE.md" "$package/licences/GLFW.txt"
cp "$sources/imgui/LICENSE.txt" "$package/licences/Dear-ImGui.txt"
sed -n '/Copyright notice:/,$p' "$sources/zlib/README" > "$package/licences/zlib.txt"
cp "$root/scripts/windows-readme.txt" "$package/README.txt"
(cd "$dir/package" && zip -q -r -9 "$dir/gsv-windows.zip" gsv-windows)
echo "windows-build: $dir/gsv-windows.zip, $(du -k "$dir/gsv-windows.zip" | cut -f1) KiB: ${#labs[@]} labs, their DLLs and files"
