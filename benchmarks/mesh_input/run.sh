#!/usr/bin/env bash
# Mesh input benchmark on a large gmsh mesh (bar_big.geo, h = 0.025: about
# 860,000 tetrahedra, 39 MB; generated into the build directory once, too
# large to commit), on 1 and 2 ranks:
#  - mesh only (scene_mesh_only.prm: it stops with an input error right after
#    the mesh is built): wall time and peak resident memory of each rank;
#  - a whole run (scene.prm, linear elasticity, one load step): the
#    "mesh and setup" time of the timer table, and peak memory per rank.
#   bash benchmarks/mesh_input/run.sh [BUILD_DIR] [h]
# HYPERELASTIC=/path/to/hyperelastic compares another build.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${1:-$root/build}
h=${2:-0.025}
binary=${HYPERELASTIC:-$build/hyperelastic}
work=$build/mesh_input_benchmark
mkdir -p "$work"
mesh=$work/bar_big.msh
if [ ! -f "$mesh" ]; then
  gmsh -3 -format msh41 -setnumber h "$h" "$here/bar_big.geo" -o "$mesh" >"$work/gmsh.log"
fi
cp "$here/scene.prm" "$here/scene_mesh_only.prm" "$work/"
cd "$work"
for np in 1 2; do
  # Each rank under /usr/bin/time: its own wall time and peak resident set.
  "$root/scripts/mpirun.sh" -np "$np" /usr/bin/time -f "rank: %e s wall, peak memory %M kB" \
    "$binary" scene_mesh_only.prm >"mesh_only_np$np.log" 2>&1 || true
  echo "== $np rank(s), mesh only: $(grep -o 'rank: .*' "mesh_only_np$np.log" | tr '\n' ' ')"
  "$root/scripts/mpirun.sh" -np "$np" /usr/bin/time -f "rank: %e s wall, peak memory %M kB" \
    "$binary" scene.prm >"run_np$np.log" 2>&1
  echo "== $np rank(s), whole run: $(grep 'mesh and setup' "run_np$np.log" | tr -s ' ')" \
       "$(grep -o 'rank: .*' "run_np$np.log" | tr '\n' ' ')"
done
