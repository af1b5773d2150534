// SPDX-License-Identifier: GPL-3.0-or-later
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

// PLY scalar types, decoded once from the header's names (not compared as strings per value).
enum class Scalar : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

Scalar scalarOf(const std::string& t) {
  if (t == "char" || t == "int8") return Scalar::Int8;
  if (t == "uchar" || t == "uint8") return Scalar::UInt8;
  if (t == "short" || t == "int16") return Scalar::Int16;
  if (t == "ushort" || t == "uint16") return Scalar::UInt16;
  if (t == "int" || t == "int32") return Scalar::Int32;
  if (t == "uint" || t == "uint32") return Scalar::UInt32;
  if (t == "float" || t == "float32") return Scalar::Float32;
  return Scalar::Float64;  // readHeader admitted only the names of typeSizes()
}

constexpr int sizeOf(Scalar s) {
  switch (s) {
    case Scalar::Int8: case Scalar::UInt8: return 1;
    case Scalar::Int16: case Scalar::UInt16: return 2;
    case Scalar::Int32: case Scalar::UInt32: case Scalar::Float32: return 4;
    case Scalar::Float64: return 8;
  }
  return 8;
}

// Where a value sits, for a message; built only when one is needed.
struct Where {
  const std::string* element;
  long long index;
  std::string text() const { return *element + " " + std::to_string(index); }
};

// The data after the header, value by value, read through a fixed buffer (the file is never
// held whole: a 131 MB file costs 1 MB here).
class Body {
 public:
  Body(const std::string& path, const Header& h)
      : path_(path), format_(h.format), in_(std::fopen(path.c_str(), "rb")), buffer_(kChunk) {
    if (!in_ || std::fseek(in_, static_cast<long>(h.bytes), SEEK_SET) != 0)
      fail(path, "cannot open for reading (permission denied?)");
  }
  ~Body() {
    if (in_) std::fclose(in_);
  }
  Body(const Body&) = delete;
  Body& operator=(const Body&) = delete;

  /// The next value of PLY type `type` (`name` its header name, for messages); `where` names it
  /// for the error if the data ends.
  double read(Scalar type, const std::string& name, const Where& where) {
    // A little-endian file on a little-endian machine, away from the buffer's end: values are
    // copied as they lie (the general path below assembles them byte by byte).
    if (kLittleHost && format_ == Format::BinaryLittle && end_ - pos_ >= 8) {
      const unsigned char* b = buffer_.data() + pos_;
      switch (type) {
        case Scalar::Float64: return take<double>(b);
        case Scalar::Float32: return take<float>(b);
        case Scalar::Int32: return take<std::int32_t>(b);
        case Scalar::UInt32: return take<std::uint32_t>(b);
        case Scalar::Int16: return take<std::int16_t>(b);
        case Scalar::UInt16: return take<std::uint16_t>(b);
        case Scalar::Int8: return take<std::int8_t>(b);
        case Scalar::UInt8: return take<std::uint8_t>(b);
      }
    }
    if (format_ == Format::Ascii) return readText(type, name, where);
    const size_t n = static_cast<size_t>(sizeOf(type));
    if (!ensure(n)) fail(path_, "truncated PLY: the file ends in " + where.text());
    const unsigned char* b = buffer_.data() + pos_;
    pos_ += n;
    const bool little = format_ == Format::BinaryLittle;
    std::uint64_t u = 0;
    for (size_t k = 0; k < n; ++k) u |= std::uint64_t(b[little ? k : n - 1 - k]) << (8 * k);
    switch (type) {
      case Scalar::Float32: {
        float f;
        const auto u32 = static_cast<std::uint32_t>(u);
        std::memcpy(&f, &u32, 4);
        return f;
      }
      case Scalar::Float64: {
        double d;
        std::memcpy(&d, &u, 8);
        return d;
      }
      case Scalar::Int8: return static_cast<std::int8_t>(u);
      case Scalar::Int16: return static_cast<std::int16_t>(u);
      case Scalar::Int32: return static_cast<std::int32_t>(u);
      default: return static_cast<double>(u);
    }
  }

 private:
  static constexpr size_t kChunk = 1 << 20;
  static constexpr bool kLittleHost = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;

  template <class T>
  double take(const unsigned char* b) {
    T value;
    std::memcpy(&value, b, sizeof value);
    pos_ += sizeof value;
    return static_cast<double>(value);
  }

  // At least `n` unread bytes in the buffer (n <= 8); false at the end of the file.
  bool ensure(size_t n) {
    if (end_ - pos_ >= n) return true;
    std::memmove(buffer_.data(), buffer_.data() + pos_, end_ - pos_);
    end_ -= pos_;
    pos_ = 0;
    end_ += std::fread(buffer_.data() + end_, 1, buffer_.size() - end_, in_);
    return end_ - pos_ >= n;
  }

  double readText(Scalar type, const std::string& name, const Where& where) {
    auto space = [](unsigned char c) { return std::isspace(c) != 0; };
    while (ensure(1) && space(buffer_[pos_])) ++pos_;
    // The token (its first kMaxToken characters: parseNumber refuses longer ones anyway, and a
    // message quotes 20); `long_` when it had more.
    token_.clear();
    bool tooLong = false;
    while (ensure(1) && !space(buffer_[pos_])) {
      if (token_.size() < kMaxToken) token_.push_back(static_cast<char>(buffer_[pos_]));
      else tooLong = true;
      ++pos_;
    }
    if (token_.empty()) fail(path_, "truncated PLY: the file ends in " + where.text());
    double x = 0;
    if (tooLong || !parseNumber(token_, x)) fail(path_, where.text() + ": " + quote(token_) + " is not a number");
    if (type != Scalar::Float32 && type != Scalar::Float64) {
      if (x != std::floor(x)) fail(path_, where.text() + ": " + quote(token_) + " is not an integer");
      // Within the declared type, as a binary file's value would be (found by fuzzing: a list
      // count of 1e300 then overflowed a conversion to an integer).
      const bool isSigned = type == Scalar::Int8 || type == Scalar::Int16 || type == Scalar::Int32;
      const int bits = 8 * sizeOf(type);
      const double lo = isSigned ? -std::ldexp(1.0, bits - 1) : 0.0;
      const double hi = std::ldexp(1.0, isSigned ? bits - 1 : bits) - 1;
      if (x < lo || x > hi) fail(path_, where.text() + ": " + quote(token_) + " is out of range for type " + name);
    }
    // A value declared float is what a float holds, as in a binary file.
    return type == Scalar::Float32 ? static_cast<double>(static_cast<float>(x)) : x;
  }

  static constexpr size_t kMaxToken = 80;
  std::string path_;
  Format format_;
  std::FILE* in_;
  std::vector<unsigned char> buffer_;
  size_t pos_ = 0, end_ = 0;
  std::string token_;
};

int findProperty(const Element& e, const std::vector<std::string>& names, bool list) {
  for (size_t i = 0; i < e.properties.size(); ++i)
    for (const auto& n : names)
      if (e.properties[i].name == n && e.properties[i].countType.empty() != list) return static_cast<int>(i);
  return -1;
}

}  // namespace

void readPly(const std::string& path, std::uintmax_t fileSize, TriMesh& mesh, std::vector<std::uint8_t>& selected,
             ReadReport& report) {
  const Header h = readHeader(path, fileSize);
  Body body(path, h);
  std::vector<Vec3>& positions = mesh.positions;
  std::vector<Face>& triangles = mesh.faces;
  long long vertexCount = -1;
  std::vector<double> values;
  std::vector<Scalar> types, countTypes;
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
    // The header proved the file can hold e.count entries of at least one byte each.
    if (isVertex) positions.reserve(static_cast<size_t>(e.count));
    if (isFace) triangles.reserve(static_cast<size_t>(e.count));
    types.clear();
    countTypes.clear();
    for (const Property& prop : e.properties) {
      types.push_back(scalarOf(prop.type));
      countTypes.push_back(prop.countType.empty() ? Scalar::UInt8 : scalarOf(prop.countType));
    }
    const int nProperties = static_cast<int>(e.properties.size());
    for (long long i = 0; i < e.count; ++i) {
      const Where where{&e.name, i};
      double p[3] = {0, 0, 0};
      bool sel = false;
      const size_t firstTriangle = triangles.size();
      for (int k = 0; k < nProperties; ++k) {
        const Property& prop = e.properties[k];
        if (prop.countType.empty()) {
          const double v = body.read(types[k], prop.type, where);
          if (k == x) p[0] = v;
          if (k == y) p[1] = v;
          if (k == z) p[2] = v;
          if (k == flags) sel = sel || (std::fabs(v) < 0x1p62 && (static_cast<long long>(v) & kPlyFaceSelected) != 0);
          if (k == selectedProperty) sel = sel || v != 0;
          continue;
        }
        const double n = body.read(countTypes[k], prop.countType, where);
        if (n < 0 || n > kMaxListSize)
          fail(path, where.text() + ": a list of " + numberText(n) + " entries (at most " +
                         std::to_string(kMaxListSize) + " read here)");
        values.resize(static_cast<size_t>(n));
        for (double& v : values) v = body.read(types[k], prop.type, where);
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
        for (size_t c = 1; c + 1 < values.size(); ++c) triangles.push_back({int(values[0]), int(values[c]), int(values[c + 1])});
      }
      if (isVertex) {
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
          fail(path, "vertex " + std::to_string(i) + " has a non-finite coordinate");
        positions.emplace_back(p[0], p[1], p[2]);
      }
      if (isFace && report.hasFaceSelection) selected.resize(triangles.size(), 0);
      if (sel) std::fill(selected.begin() + static_cast<std::ptrdiff_t>(firstTriangle), selected.end(), 1);
    }
    if (isVertex) vertexCount = e.count;
  }
}

}  // namespace elastica::io::detail
