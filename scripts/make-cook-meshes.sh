#!/usr/bin/env bash
# Regenerates the Cook's membrane meshes meshes/cook_2d_N.msh (N = 2, 4, 8,
# 16, 32) and meshes/cook_3d_N.msh (N = 2, 4, 8, 16) from meshes/cook_2d.geo
# and meshes/cook_3d.geo: structured triangles / tetrahedra with N elements
# per side, ASCII gmsh format 4.1. Needs gmsh (apt-get install gmsh).
set -euo pipefail
cd "$(dirname "$0")/../meshes"
for n in 2 4 8 16 32; do
  gmsh -2 -format msh41 -setnumber N "$n" cook_2d.geo -o "cook_2d_$n.msh" >/dev/null
  echo "meshes/cook_2d_$n.msh"
done
for n in 2 4 8 16; do
  gmsh -3 -format msh41 -setnumber N "$n" cook_3d.geo -o "cook_3d_$n.msh" >/dev/null
  echo "meshes/cook_3d_$n.msh"
done
