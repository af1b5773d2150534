// SPDX-License-Identifier: GPL-3.0-or-later
#include "face_index_file.h"

#include <elastica/errors.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace elastica::cli {

std::vector<std::uint8_t> readFaceIndexFile(const std::string& path, int faceCount) {
  std::ifstream in(path);
  if (!in) throw IoError(path + ": cannot read the face index file");
  std::vector<std::uint8_t> listed(static_cast<std::size_t>(faceCount), 0);
  std::string line;
  int lineNumber = 0, count = 0;
  while (std::getline(in, line)) {
    ++lineNumber;
    line = line.substr(0, line.find('#'));
    for (char& c : line) c = c == ',' ? ' ' : c;
    std::istringstream words(line);
    std::string word;
    while (words >> word) {
      char* end = nullptr;
      errno = 0;
      const long long index = std::strtoll(word.c_str(), &end, 10);
      if (*end != '\0' || errno == ERANGE)
        throw InvalidInputError(path + ": '" + word + "' is not a face index (line " + std::to_string(lineNumber) + ")");
      if (index < 0 || index >= faceCount)
        throw InvalidInputError(path + ": face " + word + " does not exist; the mesh has " + std::to_string(faceCount) +
                                " faces, numbered from 0 (line " + std::to_string(lineNumber) + ")");
      listed[static_cast<std::size_t>(index)] = 1;
      ++count;
    }
  }
  if (in.bad()) throw IoError(path + ": read error in the face index file");
  if (count == 0) throw InvalidInputError(path + ": the face index file lists no face");
  return listed;
}

}  // namespace elastica::cli
