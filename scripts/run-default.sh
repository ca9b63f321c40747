#!/usr/bin/env bash
# Quick start, part 1: install what is missing, build in Release and run the
# default scene on 2 MPI ranks. Output goes to output/ in the current folder.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-dependencies.sh"
"$root/scripts/build.sh"
"$root/scripts/mpirun.sh" -np 2 "$root/build/hyperelastic" "$root/parameters/default.prm"
