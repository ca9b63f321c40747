#!/usr/bin/env bash
# Hertz in 3D on finer meshes than the ctest's (contact.hertz.3d): the
# quarter block of meshes/hertz_block_3d.geo with smaller tetrahedra under
# the sphere, each run of 'build/tests/contact hertz 3 MESH 0.05' asserting
# the force and the contact radius within 5 %. Prints the checks and the wall
# time per mesh (minutes each on 2 shared cores).
# Usage: benchmarks/contact/hertz_3d.sh [HMIN ...]   (default 0.0008 0.0006)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(0.0008 0.0006)
for hmin in "${sizes[@]}"; do
  k=$(python3 -c "print(0.25 if $hmin >= 0.0008 else 0.2)")
  gmsh -3 -format msh41 -setnumber hmin "$hmin" -setnumber rfine 0.02 \
    -setnumber k "$k" "$root/meshes/hertz_block_3d.geo" \
    -o "$work/hertz_$hmin.msh" >/dev/null
  echo "== hmin = $hmin, k = $k"
  start=$(date +%s)
  "$root/scripts/mpirun.sh" -np 2 "$root/build/tests/contact" hertz 3 \
    "$work/hertz_$hmin.msh" 0.05
  echo "wall time: $(( $(date +%s) - start )) s"
done
