// SPDX-License-Identifier: GPL-3.0-or-later
// MeshLab filter scripts (.mlx), read without Qt: the <FilterScript> of <filter name="..."> with
// <Param type="Rich..." name="..." value="..."/> children that MeshLab's "Save script" writes and
// meshlabserver -s runs. Only the parts our filters use are kept (RichEnum's enum_val list is
// informative; the value is the index).
#pragma once

#include <string>
#include <vector>

namespace elastica::cli {

struct MlxParam {
  std::string type;   ///< "RichBool", "RichInt", "RichFloat", "RichEnum", ...
  std::string name;
  std::string value;  ///< as written
  int line = 0;
};

struct MlxFilter {
  std::string name;
  std::vector<MlxParam> params;
  int line = 0;
};

/// Reads the filters of `path` in order.
/// @throws IoError "<path>: ..." if the file cannot be read, is not well-formed XML, has no
///         <FilterScript> root, or a <filter>/<Param> lacks a required attribute.
std::vector<MlxFilter> readMlxScript(const std::string& path);

}  // namespace elastica::cli
