#!/usr/bin/env bash
# Configures and builds hyperelastic in build/ (Release unless BUILD_TYPE is set).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_type=${BUILD_TYPE:-Release}
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE="$build_type" >/dev/null
cmake --build "$root/build" -j "$(nproc)"
