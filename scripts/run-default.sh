#!/usr/bin/env bash
# Quick start, part 1: install what is missing, build the program in Release
# (not the test suite: scripts/test.sh builds that) and run the default scene
# on 2 MPI ranks. Output goes to output/ in the current folder.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-dependencies.sh"
"$root/scripts/build.sh" hyperelastic
"$root/scripts/mpirun.sh" -np 2 "$root/build/hyperelastic" "$root/parameters/default.prm"
