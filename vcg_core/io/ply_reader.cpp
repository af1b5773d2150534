// PLY, ASCII and binary (either byte order), read here rather than by vcglib: vcglib allocates
// whatever counts the header states (a 100-byte file claiming 3 billion vertices is an
// allocation failure or worse), reads the first three indices of a face whatever its size
// (stale values for a 2-vertex face), copies a face's list into a fixed 512-entry buffer, and
// reports a bad index without saying where. We read vertex x, y, z, face vertex_indices (or
// vertex_index; polygons fan-triangulated) and face flags (MeshLab's selection); every other
// element and property is parsed and skipped.
#include "readers.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
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

bool isFloatType(std::string_view t) { return t == "float" || t == "float32" || t == "double" || t == "float64"; }
// A value read from the file, for a message: whole numbers as integers, anything else as %g
// (converting 1e300 or NaN to an integer type would be undefined).
std::string numberText(double v) {
  if (v == std::floor(v) && std::fabs(v) < 0x1p62) return std::to_string(static_cast<long long>(v));
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

bool isSignedType(std::string_view t) { return t == "char" || t == "int8" || t == "short" || t == "int16" || t == "int" || t == "int32"; }

constexpr std::uintmax_t kMaxHeaderBytes = 1 << 20;
// A polygon larger than this is not a mesh face we can use (and bounds what a list may claim).
constexpr long long kMaxListSize = 1 << 16;

enum class Format { Ascii, BinaryLittle, BinaryBig };

struct Property {
  std::string name;
  std::string type;       // item type for a list
  std::string countType;  // empty for a scalar
};

struct Element {
  std::string name;
  long long count = 0;
  std::vector<Property> properties;
  std::uintmax_t minBytes = 0;
};

struct Header {
  Format format = Format::Ascii;
  std::vector<Element> elements;
  std::uintmax_t bytes = 0;  // header length, up to and including the end_header line
};

Header readHeader(const std::string& path, std::uintmax_t fileSize) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  long long lineNo = 0;
  Header h;
  auto at = [&] { return " (header line " + std::to_string(lineNo) + ")"; };
  auto nextLine = [&] {
    if (!std::getline(in, line) || h.bytes + line.size() > kMaxHeaderBytes)
      fail(path, "malformed PLY: the header has no end_header line");
    h.bytes += line.size() + 1;
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
  };
  nextLine();
  if (line != "ply") fail(path, "malformed PLY: the file does not start with 'ply' (found " + quote(line) + ")");

  bool haveFormat = false;
  for (nextLine(); line != "end_header"; nextLine()) {
    const auto t = splitTokens(line);
    if (t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "format") {
      if (t.size() < 2 || (t[1] != "ascii" && t[1] != "binary_little_endian" && t[1] != "binary_big_endian"))
        fail(path, "malformed PLY: unknown format " + quote(t.size() > 1 ? t[1] : "") + at());
      h.format = t[1] == "ascii" ? Format::Ascii : t[1] == "binary_little_endian" ? Format::BinaryLittle : Format::BinaryBig;
      haveFormat = true;
    } else if (t[0] == "element") {
      long long count = -1;
      if (t.size() == 3 && parseInteger(t[2], count) && count > INT_MAX)
        fail(path, "the PLY header claims " + std::to_string(count) + " " + quote(t[1]) + " elements, more than " +
                       std::to_string(INT_MAX) + " (the most a mesh can hold here)" + at());
      if (t.size() != 3 || !parseInteger(t[2], count) || count < 0)
        fail(path, "malformed PLY: expected 'element NAME COUNT' with a count in [0, " + std::to_string(INT_MAX) + "]" + at());
      h.elements.push_back({std::string(t[1]), count, {}});
    } else if (t[0] == "property") {
      if (h.elements.empty()) fail(path, "malformed PLY: a property before any element" + at());
      const bool list = t.size() >= 2 && t[1] == "list";
      if (t.size() != (list ? 5u : 3u))
        fail(path, "malformed PLY: expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'" + at());
      for (size_t k = list ? 2 : 1; k + 1 < t.size(); ++k)
        if (!typeSizes().count(t[k])) fail(path, "unknown PLY property type " + quote(t[k]) + at());
      if (list && isFloatType(t[2])) fail(path, "PLY list count type " + quote(t[2]) + " is not an integer type" + at());
      h.elements.back().properties.push_back(
          {std::string(t.back()), std::string(t[list ? 3 : 1]), list ? std::string(t[2]) : std::string()});
    } else {
      fail(path, "malformed PLY: unknown header keyword " + quote(t[0]) + at());
    }
  }
  if (!haveFormat) fail(path, "malformed PLY: no format line in the header");

  // The least each element can take (its binary sizes, or a digit and a separator per ASCII
  // value; a list at least its count): refuse counts the file cannot hold before allocating.
  const std::uintmax_t body = fileSize - std::min(fileSize, h.bytes);
  std::uintmax_t needed = 0;
  std::string claims;
  for (Element& e : h.elements) {
    for (const Property& p : e.properties)
      e.minBytes += h.format == Format::Ascii ? 2 : typeSizes().at(p.countType.empty() ? p.type : p.countType);
    if (e.count > 0 && e.minBytes == 0)
      fail(path, "malformed PLY: element " + quote(e.name) + " has " + std::to_string(e.count) + " entries but no properties");
    needed += static_cast<std::uintmax_t>(e.count) * e.minBytes;
    claims += (claims.empty() ? "" : ", ") + std::to_string(e.count) + " " + quote(e.name, 20);
  }
  if (needed > body)
    fail(path, "the PLY header claims " + claims + " elements, which need at least " + std::to_string(needed) +
                   " bytes, but the data after the header has " + std::to_string(body) + " bytes");
  return h;
}

// The data after the header, value by value.
class Body {
 public:
  Body(const std::string& path, const Header& h) : path_(path), format_(h.format) {
    std::ifstream in(path, std::ios::binary);
    in.seekg(static_cast<std::streamoff>(h.bytes));
    data_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  /// The next value of PLY type `type`; `where` names it for the error if the data ends.
  double read(const std::string& type, const std::string& where) {
    if (format_ == Format::Ascii) {
      while (pos_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[pos_]))) ++pos_;
      const size_t start = pos_;
      while (pos_ < data_.size() && !std::isspace(static_cast<unsigned char>(data_[pos_]))) ++pos_;
      if (pos_ == start) fail(path_, "truncated PLY: the file ends in " + where);
      const std::string_view token(data_.data() + start, pos_ - start);
      double x = 0;
      if (!parseNumber(token, x)) fail(path_, where + ": " + quote(token) + " is not a number");
      if (!isFloatType(type)) {
        if (x != std::floor(x)) fail(path_, where + ": " + quote(token) + " is not an integer");
        // Within the declared type, as a binary file's value would be (found by fuzzing: a list
        // count of 1e300 then overflowed a conversion to an integer).
        const int bits = 8 * typeSizes().at(type);
        const double lo = isSignedType(type) ? -std::ldexp(1.0, bits - 1) : 0.0;
        const double hi = std::ldexp(1.0, isSignedType(type) ? bits - 1 : bits) - 1;
        if (x < lo || x > hi) fail(path_, where + ": " + quote(token) + " is out of range for type " + type);
      }
      // A value declared float is what a float holds, as in a binary file.
      return type == "float" || type == "float32" ? static_cast<double>(static_cast<float>(x)) : x;
    }
    const size_t n = static_cast<size_t>(typeSizes().at(type));
    if (data_.size() - pos_ < n) fail(path_, "truncated PLY: the file ends in " + where);
    unsigned char b[8];
    std::memcpy(b, data_.data() + pos_, n);
    pos_ += n;
    const bool little = format_ == Format::BinaryLittle;
    std::uint64_t u = 0;
    for (size_t k = 0; k < n; ++k) u |= std::uint64_t(b[little ? k : n - 1 - k]) << (8 * k);
    if (type == "float" || type == "float32") {
      float f;
      const auto u32 = static_cast<std::uint32_t>(u);
      std::memcpy(&f, &u32, 4);
      return f;
    }
    if (type == "double" || type == "float64") {
      double d;
      std::memcpy(&d, &u, 8);
      return d;
    }
    if (isSignedType(type) && (u >> (8 * n - 1)) & 1) return static_cast<double>(static_cast<std::int64_t>(u) - (std::int64_t(1) << (8 * n)));
    return static_cast<double>(u);
  }

 private:
  std::string path_;
  Format format_;
  std::vector<char> data_;
  size_t pos_ = 0;
};

int findProperty(const Element& e, const std::vector<std::string>& names, bool list) {
  for (size_t i = 0; i < e.properties.size(); ++i)
    for (const auto& n : names)
      if (e.properties[i].name == n && e.properties[i].countType.empty() != list) return static_cast<int>(i);
  return -1;
}

}  // namespace

void readPly(const std::string& path, std::uintmax_t fileSize, VcgMesh& m, ReadReport& report) {
  const Header h = readHeader(path, fileSize);
  Body body(path, h);
  std::vector<vcg::Point3d> positions;
  std::vector<std::array<int, 3>> triangles;
  std::vector<char> selected;
  long long vertexCount = -1;
  std::vector<double> values;
  for (const Element& e : h.elements) {
    const bool isVertex = e.name == "vertex" && vertexCount < 0, isFace = e.name == "face" && triangles.empty();
    const int x = isVertex ? findProperty(e, {"x"}, false) : -1, y = isVertex ? findProperty(e, {"y"}, false) : -1,
              z = isVertex ? findProperty(e, {"z"}, false) : -1;
    const int idx = isFace ? findProperty(e, {"vertex_indices", "vertex_index"}, true) : -1;
    const int flags = isFace ? findProperty(e, {"flags"}, false) : -1;
    const int selectedProperty = isFace ? findProperty(e, {"selected"}, false) : -1;  // non-zero: selected
    if (isVertex && e.count > 0 && (x < 0 || y < 0 || z < 0)) fail(path, "PLY vertex element without x, y and z properties");
    if (isFace && e.count > 0 && idx < 0) fail(path, "PLY face element without a vertex_indices list");
    if (isFace && vertexCount < 0) fail(path, "PLY face element before the vertex element");
    if (isFace) report.hasFaceSelection = flags >= 0 || selectedProperty >= 0;
    for (long long i = 0; i < e.count; ++i) {
      const std::string where = e.name + " " + std::to_string(i);
      double p[3] = {0, 0, 0};
      bool sel = false;
      const size_t firstTriangle = triangles.size();
      for (int k = 0; k < static_cast<int>(e.properties.size()); ++k) {
        const Property& prop = e.properties[k];
        if (prop.countType.empty()) {
          const double v = body.read(prop.type, where);
          if (k == x) p[0] = v;
          if (k == y) p[1] = v;
          if (k == z) p[2] = v;
          if (k == flags) sel = sel || (std::fabs(v) < 0x1p62 && (static_cast<long long>(v) & VcgFace::SELECTED) != 0);
          if (k == selectedProperty) sel = sel || v != 0;
          continue;
        }
        const double n = body.read(prop.countType, where);
        if (n < 0 || n > kMaxListSize)
          fail(path, where + ": a list of " + numberText(n) + " entries (at most " +
                         std::to_string(kMaxListSize) + " read here)");
        values.resize(static_cast<size_t>(n));
        for (double& v : values) v = body.read(prop.type, where);
        if (k != idx) continue;
        if (values.size() < 3)
          fail(path, "face " + std::to_string(i) + " has " + std::to_string(values.size()) + " vertices (a face needs at least 3)");
        for (double v : values)
          if (!(v >= 0 && v < static_cast<double>(vertexCount)))  // NaN too (a float-typed index list)
            fail(path, "face " + std::to_string(i) + " refers to vertex " + numberText(v) + ", but the file has " +
                           std::to_string(vertexCount) + " vertices");
          else if (v != std::floor(v))
            fail(path, "face " + std::to_string(i) + " refers to vertex " + numberText(v) + " (not a whole number)");
        if (values.size() > 3) ++report.polygonsTriangulated;
        for (size_t c = 1; c + 1 < values.size(); ++c) {
          triangles.push_back({int(values[0]), int(values[c]), int(values[c + 1])});
          selected.push_back(0);
        }
      }
      if (isVertex) {
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
          fail(path, "vertex " + std::to_string(i) + " has a non-finite coordinate");
        positions.emplace_back(p[0], p[1], p[2]);
      }
      if (sel) std::fill(selected.begin() + static_cast<std::ptrdiff_t>(firstTriangle), selected.end(), 1);
    }
    if (isVertex) vertexCount = e.count;
  }
  auto vi = vcg::tri::Allocator<VcgMesh>::AddVertices(m, positions.size());
  for (const auto& p : positions) (vi++)->P() = p;
  auto fi = vcg::tri::Allocator<VcgMesh>::AddFaces(m, triangles.size());
  for (size_t t = 0; t < triangles.size(); ++t, ++fi) {
    for (int k = 0; k < 3; ++k) fi->V(k) = &m.vert[triangles[t][k]];
    if (selected[t]) fi->SetS();
  }
}

}  // namespace elastica::io::detail
