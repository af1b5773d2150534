// Procedural meshes with known curvature: the analytic references of the tests, the benchmarks
// and `elastica generate`.
#pragma once

#include <elastica/types.h>

namespace elastica::shapes {

/// Icosahedron refined `level` times by 1-to-4 midpoint subdivision, vertices projected onto the
/// sphere of `radius` centred at the origin: 10·4^level + 2 vertices (level 5: 10,242). Outward.
TriMesh icosphere(double radius, int level);

/// Torus of revolution around z: tube radius r at distance R from the axis, `nu` segments around
/// the axis and `nv` around the tube, each quad split along a diagonal. Outward oriented.
TriMesh torus(double R, double r, int nu, int nv);

/// Flat (nx+1)×(ny+1) grid in the plane z = 0 with `spacing`, quads split along alternating
/// diagonals, normals +z. Has a boundary.
TriMesh grid(int nx, int ny, double spacing = 1.0);

/// Moves each vertex radially (from the origin) by a factor drawn uniformly from
/// [1 − amplitude, 1 + amplitude], reproducibly for a given seed: the noisy spheres of the tests.
void addRadialNoise(TriMesh& mesh, double amplitude, unsigned seed);

}  // namespace elastica::shapes
