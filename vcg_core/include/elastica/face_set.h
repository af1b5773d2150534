// SPDX-License-Identifier: GPL-3.0-or-later
// A set of faces by index: the region a function works on (a user's selection, a patch).
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace elastica {

/// Faces of one TriMesh by index, in any order; repeats are allowed and count once.
/// The constructor is explicit so that `fair(mesh, {})` means default options, not an empty region.
struct FaceSet {
  std::vector<int> faces;

  explicit FaceSet(std::vector<int> faceIndices) : faces(std::move(faceIndices)) {}

  /// The faces whose flag is non-zero (one byte per face, as vcglib's and MeshLab's selection).
  static FaceSet fromFlags(const std::vector<std::uint8_t>& flags);

  /// One byte per face of a mesh with `faceCount` faces: 1 on the set's faces, 0 elsewhere.
  /// @throws InvalidInputError if an index is negative or not below faceCount.
  std::vector<std::uint8_t> flags(std::size_t faceCount) const;
};

}  // namespace elastica
