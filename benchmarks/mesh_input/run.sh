#!/usr/bin/env bash
# Mesh input benchmark: "mesh and setup" wall time (timer table of the run)
# and peak resident memory per rank for a large gmsh mesh, on 1 and 2 ranks.
#   bash benchmarks/mesh_input/run.sh [BUILD_DIR] [h]
# The mesh (bar_big.geo, h = 0.025: ~875,000 tetrahedra, 39 MB) is generated
# into the build directory once; it is too large to commit.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${1:-$root/build}
h=${2:-0.025}
work=$build/mesh_input_benchmark
mkdir -p "$work"
mesh=$work/bar_big.msh
if [ ! -f "$mesh" ]; then
  gmsh -3 -format msh41 -setnumber h "$h" "$here/bar_big.geo" -o "$mesh" >"$work/gmsh.log"
fi
cp "$here/scene.prm" "$work/scene.prm"
cd "$work"
for np in 1 2; do
  # Each rank under /usr/bin/time: its own peak resident set (kB).
  "$root/scripts/mpirun.sh" -np "$np" /usr/bin/time -f "rank peak memory: %M kB" \
    "$build/hyperelastic" scene.prm >"run_np$np.log" 2>&1
  echo "== $np rank(s)"
  grep -E "mesh and setup|rank peak memory|Total wallclock" "run_np$np.log"
done
