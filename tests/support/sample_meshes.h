// SPDX-License-Identifier: GPL-3.0-or-later
// The real sample meshes scripts/setup.sh fetches from Debian's libcgal-demo, read as a test needs
// them (ELASTICA_SAMPLE_MESH_DIR is the test program's definition).
#pragma once

#include <elastica/io/mesh_reader.h>
#include <elastica/types.h>
#include <elastica/vcg_adapter.h>
#include <elastica/vcg_mesh.h>

#include <string>

namespace elastica::test {

/// `name` (e.g. "cow.off") from the sample mesh folder, through the readers' checks and repairs.
inline TriMesh readSample(const std::string& name) {
  VcgMesh vm;
  io::readMesh(std::string(ELASTICA_SAMPLE_MESH_DIR) + "/" + name, vm);
  return toTriMesh(vm);
}

}  // namespace elastica::test
