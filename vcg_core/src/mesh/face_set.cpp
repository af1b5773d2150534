// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/errors.h>
#include <elastica/face_set.h>

#include <string>

namespace elastica {

FaceSet FaceSet::fromFlags(const std::vector<std::uint8_t>& flags) {
  std::vector<int> faces;
  for (std::size_t f = 0; f < flags.size(); ++f)
    if (flags[f]) faces.push_back(static_cast<int>(f));
  return FaceSet(std::move(faces));
}

std::vector<std::uint8_t> FaceSet::flags(std::size_t faceCount) const {
  std::vector<std::uint8_t> out(faceCount, 0);
  for (int f : faces) {
    if (f < 0 || static_cast<std::size_t>(f) >= faceCount)
      throw InvalidInputError("face " + std::to_string(f) + " is not a face of a mesh with " +
                              std::to_string(faceCount) + " faces");
    out[static_cast<std::size_t>(f)] = 1;
  }
  return out;
}

}  // namespace elastica
