#!/bin/sh
# Regenerates the Gmsh test files of this folder from the .geo files with the gmsh binary
# (the checked-in files were made by Gmsh 4.8.4). tests/scenario/test_mesh_format_gmsh.cpp
# runs the same commands in a temporary folder when gmsh is on PATH.
#   usage: tests/data/gmsh/make.sh [gmsh]
set -eu
GMSH=${1:-gmsh}
cd "$(dirname "$0")"
mesh() { # geo, output, options...
    geo=$1; out=$2; shift 2
    "$GMSH" -3 "$geo" -o "$out" "$@" -v 1
}
mesh box.geo box_22.msh -format msh22
mesh box.geo box_22_bin.msh -format msh22 -bin
mesh box.geo box_41.msh -format msh41
mesh box.geo box_41_bin.msh -format msh41 -bin
mesh two_regions.geo two_regions_22.msh -format msh22
mesh two_regions.geo two_regions_41_bin.msh -format msh41 -bin
mesh box.geo box_order2_22.msh -format msh22 -order 2
mesh box.geo box_order2_41.msh -format msh41 -order 2
mesh mixed.geo mixed_41.msh -format msh41
mesh mixed.geo mixed_22_bin.msh -format msh22 -bin
