// A PLY header read before vcglib reads the file: vcglib allocates every element count the
// header states (a 100-byte file claiming 3 billion vertices ends in an allocation failure or
// worse) and reports an unknown type only as "Bad type name".
#include "readers.h"

#include <climits>
#include <fstream>
#include <map>

namespace elastica::io::detail {
namespace {

// Bytes of each PLY scalar type in a binary file (both the old and the sized names).
const std::map<std::string_view, int>& typeSizes() {
  static const std::map<std::string_view, int> sizes{
      {"char", 1},  {"uchar", 1},  {"int8", 1},  {"uint8", 1},   {"short", 2},   {"ushort", 2},
      {"int16", 2}, {"uint16", 2}, {"int", 4},   {"uint", 4},    {"int32", 4},   {"uint32", 4},
      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
  return sizes;
}

bool isIntegerType(std::string_view t) { return t.find("int") != std::string_view::npos || t.find("char") != std::string_view::npos || t == "short" || t == "ushort"; }

constexpr std::uintmax_t kMaxHeaderBytes = 1 << 20;

}  // namespace

void checkPlyHeader(const std::string& path, std::uintmax_t fileSize) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  long long lineNo = 0;
  std::uintmax_t headerBytes = 0;
  auto at = [&] { return " (header line " + std::to_string(lineNo) + ")"; };
  auto nextLine = [&] {
    if (!std::getline(in, line) || headerBytes + line.size() > kMaxHeaderBytes)
      fail(path, "malformed PLY: the header has no end_header line");
    headerBytes += line.size() + 1;
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
  };
  nextLine();
  if (line != "ply") fail(path, "malformed PLY: the file does not start with 'ply' (found " + quote(line) + ")");

  bool binary = false, haveFormat = false;
  struct Element { std::string name; long long count; std::uintmax_t minBytes = 0; };
  std::vector<Element> elements;
  for (nextLine(); line != "end_header"; nextLine()) {
    const auto t = splitTokens(line);
    if (t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "format") {
      if (t.size() < 2 || (t[1] != "ascii" && t[1] != "binary_little_endian" && t[1] != "binary_big_endian"))
        fail(path, "malformed PLY: unknown format " + quote(t.size() > 1 ? t[1] : "") + at());
      binary = t[1] != "ascii";
      haveFormat = true;
    } else if (t[0] == "element") {
      long long count = -1;
      if (t.size() == 3 && parseInteger(t[2], count) && count > INT_MAX)
        fail(path, "the PLY header claims " + std::to_string(count) + " " + quote(t[1]) + " elements, more than " +
                       std::to_string(INT_MAX) + " (the most a mesh can hold here)" + at());
      if (t.size() != 3 || !parseInteger(t[2], count) || count < 0)
        fail(path, "malformed PLY: expected 'element NAME COUNT' with a count in [0, " + std::to_string(INT_MAX) + "]" + at());
      elements.push_back({std::string(t[1]), count});
    } else if (t[0] == "property") {
      if (elements.empty()) fail(path, "malformed PLY: a property before any element" + at());
      const bool list = t.size() >= 2 && t[1] == "list";
      if (t.size() != (list ? 5u : 3u)) fail(path, "malformed PLY: expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'" + at());
      for (size_t k = list ? 2 : 1; k + 1 < t.size(); ++k)
        if (!typeSizes().count(t[k])) fail(path, "unknown PLY property type " + quote(t[k]) + at());
      if (list && !isIntegerType(t[2])) fail(path, "PLY list count type " + quote(t[2]) + " is not an integer type" + at());
      // The least a value can take: its binary size, or a digit and a separator in ASCII.
      elements.back().minBytes += binary ? typeSizes().at(t[list ? 2 : 1]) : 2;
    } else {
      fail(path, "malformed PLY: unknown header keyword " + quote(t[0]) + at());
    }
  }
  if (!haveFormat) fail(path, "malformed PLY: no format line in the header");
  const std::uintmax_t body = fileSize - std::min(fileSize, headerBytes);
  std::uintmax_t needed = 0;
  std::string claims;
  for (const Element& e : elements) {
    if (e.count > 0 && e.minBytes == 0)
      fail(path, "malformed PLY: element " + quote(e.name) + " has " + std::to_string(e.count) + " entries but no properties");
    needed += static_cast<std::uintmax_t>(e.count) * e.minBytes;
    claims += (claims.empty() ? "" : ", ") + std::to_string(e.count) + " " + quote(e.name, 20);
  }
  if (needed > body)
    fail(path, "the PLY header claims " + claims + " elements, which need at least " + std::to_string(needed) +
                   " bytes, but the data after the header has " + std::to_string(body) + " bytes");
}

}  // namespace elastica::io::detail
