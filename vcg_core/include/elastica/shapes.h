// SPDX-License-Identifier: GPL-3.0-or-later
// Procedural meshes with known curvature: the analytic references of the tests, the benchmarks
// and `elastica generate`.
#pragma once

#include <elastica/types.h>

#include <array>
#include <vector>

namespace elastica::shapes {

/// Icosahedron refined `level` times by 1-to-4 midpoint subdivision, vertices projected onto the
/// sphere of `radius` centred at the origin: 10·4^level + 2 vertices (level 5: 10,242). Outward.
TriMesh icosphere(double radius, int level);

/// Torus of revolution around z: tube radius r at distance R from the axis, `nu` segments around
/// the axis and `nv` around the tube, each quad split along a diagonal. Outward oriented.
TriMesh torus(double R, double r, int nu, int nv);

/// Open cylinder around z of `radius` from z = 0 to z = `height`: `around` segments around the
/// axis, `along` rows along it, quads split along alternating diagonals. Outward oriented; its two
/// end circles are boundary loops. Not a Willmore surface: the elastica flow pushes it outward.
TriMesh cylinder(double radius, double height, int around, int along);

/// Flat (nx+1)×(ny+1) grid in the plane z = 0 with `spacing`, quads split along alternating
/// diagonals, normals +z. Has a boundary.
TriMesh grid(int nx, int ny, double spacing = 1.0);

/// Closed surface of a union of unit cubes (voxels) `cells`, outward oriented, each square split
/// into four triangles around its centre (no valence-3 spike tips). Cells must not touch along an edge or a corner only (that would make the
/// surface non-manifold).
TriMesh voxelSurface(const std::vector<std::array<int, 3>>& cells);

/// The tubular cage of the paper's Figs. 1 and 5–7, made of square tubes one unit thick: a flat
/// frame of unit cubes around windowsX × windowsY square windows of side `windowSize` (2 × 1
/// windows: genus 2). Measured: with 1-unit windows the elastica flow pinches the holes and folds
/// the mesh; 2-unit windows flow cleanly once the cage is subdivided once.
TriMesh frameCage(int windowsX, int windowsY, int windowSize = 2);

/// Moves each vertex radially (from the origin) by a factor drawn uniformly from
/// [1 − amplitude, 1 + amplitude], reproducibly for a given seed: the noisy spheres of the tests.
void addRadialNoise(TriMesh& mesh, double amplitude, unsigned seed);

}  // namespace elastica::shapes
