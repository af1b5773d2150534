// SPDX-License-Identifier: GPL-3.0-or-later
#include "mlx_script.h"

#include <elastica/errors.h>

#include <tinyxml2.h>

namespace elastica::cli {

std::vector<MlxFilter> readMlxScript(const std::string& path) {
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(path.c_str()) != tinyxml2::XML_SUCCESS) {
    const std::string what = doc.ErrorID() == tinyxml2::XML_ERROR_FILE_NOT_FOUND ? "file not found"
                             : doc.ErrorID() == tinyxml2::XML_ERROR_FILE_COULD_NOT_BE_OPENED
                                 ? "cannot be opened"
                                 : std::string("not well-formed XML (") + doc.ErrorStr() + ")";
    throw IoError(path + ": " + what);
  }
  const tinyxml2::XMLElement* root = doc.RootElement();
  if (!root || std::string(root->Name()) != "FilterScript")
    throw IoError(path + ": not a MeshLab filter script (the root element must be <FilterScript>)");

  std::vector<MlxFilter> filters;
  auto required = [&](const tinyxml2::XMLElement* e, const char* attribute) {
    const char* v = e->Attribute(attribute);
    if (!v)
      throw IoError(path + ":" + std::to_string(e->GetLineNum()) + ": <" + e->Name() + "> has no " + attribute +
                    " attribute");
    return std::string(v);
  };
  // meshlabserver ignores elements other than <filter> (and other than <Param> inside one); so do we.
  for (const auto* f = root->FirstChildElement("filter"); f; f = f->NextSiblingElement("filter")) {
    MlxFilter filter{required(f, "name"), {}, f->GetLineNum()};
    for (const auto* p = f->FirstChildElement("Param"); p; p = p->NextSiblingElement("Param"))
      filter.params.push_back({required(p, "type"), required(p, "name"), required(p, "value"), p->GetLineNum()});
    filters.push_back(std::move(filter));
  }
  return filters;
}

}  // namespace elastica::cli
