#!/usr/bin/env bash
# Regenerates the gmsh-written files of this folder (test_mesh_format_vtk_medit):
#   box.vtk      legacy VTK 2.0 ASCII      box-bin.vtk  legacy VTK 2.0 binary
#   box.mesh     Medit .mesh
# Needs gmsh on PATH. -save_all keeps every element (also those of no physical group), so
# that the readers have lines, triangles and points to drop.
set -euo pipefail
cd "$(dirname "$0")"
gmsh -3 -save_all box.geo -format vtk -o box.vtk >/dev/null
gmsh -3 -save_all -bin box.geo -format vtk -o box-bin.vtk >/dev/null
gmsh -3 -save_all box.geo -format mesh -o box.mesh >/dev/null
