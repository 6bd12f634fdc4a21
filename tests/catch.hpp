#pragma once
// Catch2 v2 (Debian bookworm) and v3 (Homebrew, vcpkg) name their single include differently.
#if __has_include(<catch2/catch_all.hpp>)
#include <catch2/catch_all.hpp>
#else
#include <catch2/catch.hpp>
#endif
