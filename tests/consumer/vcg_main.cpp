// SPDX-License-Identifier: GPL-3.0-or-later
// The installed vcglib adapters: a TriMesh into a vcglib mesh and back, bit for bit.
#include <elastica/elastica.h>
#include <elastica/vcg_adapter.h>
#include <elastica/vcg_mesh.h>

#include <cstdio>

int main() {
  const elastica::TriMesh sphere = elastica::shapes::icosphere(1.0, 2);
  elastica::VcgMesh vm;
  elastica::fromTriMesh(sphere, vm);
  const elastica::TriMesh back = elastica::toTriMesh(vm);
  const bool same = back.positions == sphere.positions && back.faces == sphere.faces;
  std::printf("vcglib round trip of %d vertices, %d faces: %s\n", sphere.vertexCount(), sphere.faceCount(),
              same ? "identical" : "DIFFERENT");
  return same ? 0 : 1;
}
