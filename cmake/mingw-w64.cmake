# Cross-building the kit for 64-bit Windows with Debian's mingw-w64 (the posix-thread GCC, which std::thread needs).
# scripts/windows-build.sh passes GSV_WINDOWS_DEPS, the prefix it built GLFW, zlib and Dear ImGui into from Debian's
# source packages; glm, nlohmann_json and stb are header-only and linked into that prefix, so nothing is searched
# for in the host's /usr (its glibc headers would shadow mingw's).
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CMAKE_C_COMPILER x86_64-w64-mingw32-gcc-posix)
set(CMAKE_CXX_COMPILER x86_64-w64-mingw32-g++-posix)
set(CMAKE_RC_COMPILER x86_64-w64-mingw32-windres)
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES GSV_WINDOWS_DEPS)
set(CMAKE_FIND_ROOT_PATH /usr/x86_64-w64-mingw32 ${GSV_WINDOWS_DEPS})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
