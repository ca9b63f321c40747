#!/usr/bin/env bash
# Hertz in 3D on other meshes than the ctest's (contact.hertz.3d): the
# quarter block of meshes/hertz_block_3d.geo with other gradings, each run of
# 'build/tests/contact hertz 3 MESH 0.05' asserting the force and the contact
# radius within 5 %. Prints the vertex count, the checks and the wall time
# per mesh (from half a minute to minutes each on 2 shared cores).
# Usage: benchmarks/contact/hertz_3d.sh [HMIN:RFINE:K ...]
#   HMIN the tetrahedra's size within RFINE of the origin, K the slope of
#   their growth beyond; default: the gradings of benchmarks/contact/README.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
specs=("$@")
[ ${#specs[@]} -gt 0 ] || specs=(0.0012:0.015:0.3 0.003:0.03:0.15
  0.0025:0.03:0.15 0.002:0.025:0.15 0.0015:0.02:0.15 0.002:0.03:0.12
  0.0022:0.035:0.12 0.0025:0.04:0.1)
for spec in "${specs[@]}"; do
  IFS=: read -r hmin rfine k <<<"$spec"
  mesh="$work/hertz_${hmin}_${rfine}_${k}.msh"
  gmsh -3 -format msh41 -setnumber hmin "$hmin" -setnumber rfine "$rfine" \
    -setnumber k "$k" "$root/meshes/hertz_block_3d.geo" -o "$mesh" >/dev/null
  vertices=$(awk '/^\$Nodes/ {getline; print $2; exit}' "$mesh")
  echo "== hmin = $hmin, rfine = $rfine, k = $k: $vertices vertices"
  start=$(date +%s)
  "$root/scripts/mpirun.sh" -np 2 "$root/build/tests/contact" hertz 3 \
    "$mesh" 0.05 || true
  echo "wall time: $(( $(date +%s) - start )) s"
done
