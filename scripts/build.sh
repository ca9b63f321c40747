#!/usr/bin/env bash
# Configures and builds hyperelastic in build/ (Release unless BUILD_TYPE is set):
# every target, or only the targets named as arguments (scripts/build.sh
# hyperelastic: the program without the test suite).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_type=${BUILD_TYPE:-Release}
launcher=()
# ccache, where installed, makes rebuilds after a branch switch cheap.
# CCACHE_BASEDIR makes the paths under the checkout relative and
# CCACHE_NOHASHDIR leaves the build folder out of the hash (deal.II's flags
# have -g), so that another clone of the repository (CI's) finds the objects
# this one compiled. The sloppiness lets ccache cache compiles that use the
# precompiled headers (cmake/build_speed.cmake).
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=1
  export CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
fi
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE="$build_type" "${launcher[@]}" >/dev/null
targets=()
for target in "$@"; do
  targets+=(--target "$target")
done
cmake --build "$root/build" -j "$(nproc)" "${targets[@]}"
