// SPDX-License-Identifier: GPL-3.0-or-later
// PLY straight from arrays. The layout is vcglib's ExporterPLY's for our double VcgMesh, kept
// byte for byte (files written before and after this writer compare equal): the header with its
// "comment VCGLIB generated" line, x y z [nx ny nz] [red green blue alpha] [quality] [float
// attributes] per vertex, "list uchar int vertex_indices" [flags] [float attributes] per face;
// in ASCII, doubles as %.16g, float attributes as %f, every value followed by a space. Rows are
// formatted into a buffer written a megabyte at a time (vcglib wrote each value by fwrite).
// writeMesh picks the format from the file's extension: OFF, OBJ and STL carry positions and
// faces (OFF also vertex colours), with doubles printed exactly (%.17g) where the format is text.
#include <elastica/errors.h>
#include <elastica/io/atomic_file.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/io/mesh_writer.h>

#include <array>
#include <cerrno>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <memory>

namespace elastica::io {
namespace {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the binary PLY writer copies values in memory order");

class Output {
 public:
  Output(const std::string& path, const std::string& tmp)
      : path_(path), file_(std::fopen(tmp.c_str(), "wb")), buffer_(new char[kCapacity]) {
    if (!file_) failed();
  }
  ~Output() {
    if (file_) std::fclose(file_);
  }
  Output(const Output&) = delete;
  Output& operator=(const Output&) = delete;

  template <class T>
  void binary(T value) {
    room(sizeof value);
    std::memcpy(buffer_.get() + used_, &value, sizeof value);
    used_ += sizeof value;
  }
  void text(const char* format, ...) __attribute__((format(printf, 2, 3))) {
    // At most three %.16g numbers (24 characters each: "-1.234567890123456e-308") and spaces.
    char line[128];
    va_list args;
    va_start(args, format);
    const int n = std::vsnprintf(line, sizeof line, format, args);
    va_end(args);
    if (n < 0 || n >= static_cast<int>(sizeof line)) throw IoError(path_ + ": writing failed (a value too long to format)");
    bytes(line, static_cast<size_t>(n));
  }
  void raw(const std::string& s) { bytes(s.data(), s.size()); }
  void endRow() {
    if (used_ >= kFlush) flush();
  }
  void close() {
    flush();
    FILE* f = file_;
    file_ = nullptr;
    if (std::fclose(f) != 0) failed();
  }

 private:
  // Rows go into a fixed buffer by memcpy (a std::vector's range insert per value took 3 % of a
  // 2.6-million-vertex curvature run), written out once it holds a megabyte.
  static constexpr size_t kFlush = 1 << 20;
  static constexpr size_t kCapacity = kFlush + 4096;
  // At least n free bytes after used_, or an empty buffer (a longer string is written directly).
  void room(size_t n) {
    if (used_ + n > kCapacity) flush();
  }
  void bytes(const char* b, size_t n) {
    room(n);
    if (n > kCapacity) {
      if (std::fwrite(b, 1, n, file_) != n) failed();
      return;
    }
    std::memcpy(buffer_.get() + used_, b, n);
    used_ += n;
  }
  void flush() {
    if (used_ > 0 && std::fwrite(buffer_.get(), 1, used_, file_) != used_) failed();
    used_ = 0;
  }
  [[noreturn]] void failed() const {
    throw IoError(path_ + ": writing failed (" + std::strerror(errno) + ")");
  }
  std::string path_;
  std::FILE* file_;
  std::unique_ptr<char[]> buffer_;
  size_t used_ = 0;
};

template <class T>
void checkLength(const std::string& path, const std::vector<T>* values, size_t n, const std::string& what) {
  if (values && values->size() != n)
    throw IoError(path + ": " + what + " has " + std::to_string(values->size()) + " values for " + std::to_string(n) +
                  " elements; nothing written");
}

std::string header(const TriMesh& mesh, const PlyAttributes& a, bool binary) {
  std::string h = std::string("ply\nformat ") + (binary ? "binary_little_endian" : "ascii") +
                  " 1.0\ncomment VCGLIB generated\n";
  h += "element vertex " + std::to_string(mesh.positions.size()) + "\nproperty double x\nproperty double y\nproperty double z\n";
  if (a.vertexNormals) h += "property double nx\nproperty double ny\nproperty double nz\n";
  if (a.vertexColors) h += "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n";
  if (a.vertexQuality) h += "property double quality\n";
  for (const PlyFloatProperty& p : a.vertexFloats) h += "property float " + p.name + "\n";
  h += "element face " + std::to_string(mesh.faces.size()) + "\nproperty list uchar int vertex_indices\n";
  if (a.faceFlags) h += "property int flags\n";
  for (const PlyFloatProperty& p : a.faceFloats) h += "property float " + p.name + "\n";
  return h + "end_header\n";
}

void writeBody(Output& out, const TriMesh& mesh, const PlyAttributes& a, bool binary) {
  constexpr int kDigits = 16;  // vcglib's Precision<double>::digits()
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3& p = mesh.positions[v];
    if (binary) {
      for (int k = 0; k < 3; ++k) out.binary(p[k]);
      if (a.vertexNormals)
        for (int k = 0; k < 3; ++k) out.binary((*a.vertexNormals)[v][k]);
      if (a.vertexColors)
        for (std::uint8_t c : (*a.vertexColors)[v]) out.binary(c);
      if (a.vertexQuality) out.binary((*a.vertexQuality)[v]);
      for (const PlyFloatProperty& f : a.vertexFloats) out.binary((*f.values)[v]);
    } else {
      out.text("%.*g %.*g %.*g ", kDigits, p[0], kDigits, p[1], kDigits, p[2]);
      if (a.vertexNormals) {
        const Vec3& n = (*a.vertexNormals)[v];
        out.text("%.*g %.*g %.*g ", kDigits, n[0], kDigits, n[1], kDigits, n[2]);
      }
      if (a.vertexColors) {
        const auto& c = (*a.vertexColors)[v];
        out.text("%d %d %d %d ", c[0], c[1], c[2], c[3]);
      }
      if (a.vertexQuality) out.text("%.*g ", kDigits, (*a.vertexQuality)[v]);
      for (const PlyFloatProperty& f : a.vertexFloats) out.text("%f ", static_cast<double>((*f.values)[v]));
      out.raw("\n");
    }
    out.endRow();
  }
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const Face& t = mesh.faces[f];
    if (binary) {
      out.binary(std::uint8_t{3});
      for (int v : t) out.binary(static_cast<std::int32_t>(v));
      if (a.faceFlags) out.binary(static_cast<std::int32_t>((*a.faceFlags)[f]));
      for (const PlyFloatProperty& p : a.faceFloats) out.binary((*p.values)[f]);
    } else {
      out.text("3 %d %d %d ", t[0], t[1], t[2]);
      if (a.faceFlags) out.text("%d ", (*a.faceFlags)[f]);
      for (const PlyFloatProperty& p : a.faceFloats) out.text("%f ", static_cast<double>((*p.values)[f]));
      out.raw("\n");
    }
    out.endRow();
  }
}

// Attributes `a` holds that `format` cannot carry, by name, in member order.
std::vector<std::string> droppedBy(MeshFormat format, const PlyAttributes& a) {
  std::vector<std::string> dropped;
  if (format == MeshFormat::Ply) return dropped;
  if (a.vertexNormals) dropped.push_back("vertex normals");
  if (a.vertexColors && format != MeshFormat::Off) dropped.push_back("vertex colours");
  if (a.vertexQuality) dropped.push_back("vertex quality");
  for (const PlyFloatProperty& p : a.vertexFloats) dropped.push_back(p.name);
  if (a.faceFlags) dropped.push_back("face flags (the selection)");
  for (const PlyFloatProperty& p : a.faceFloats) dropped.push_back(p.name);
  return dropped;
}

constexpr int kExactDigits = 17;  // enough to read every double back exactly

// OFF ("COFF" with r g b a per vertex when colours are given); ASCII only.
void writeOff(Output& out, const TriMesh& mesh, const PlyAttributes& a) {
  out.raw(a.vertexColors ? "COFF\n" : "OFF\n");
  out.raw(std::to_string(mesh.positions.size()) + " " + std::to_string(mesh.faces.size()) + " 0\n");
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3& p = mesh.positions[v];
    out.text("%.*g %.*g %.*g", kExactDigits, p[0], kExactDigits, p[1], kExactDigits, p[2]);
    if (a.vertexColors) {
      const auto& c = (*a.vertexColors)[v];
      out.text(" %d %d %d %d", c[0], c[1], c[2], c[3]);
    }
    out.raw("\n");
    out.endRow();
  }
  for (const Face& t : mesh.faces) {
    out.text("3 %d %d %d\n", t[0], t[1], t[2]);
    out.endRow();
  }
}

// Wavefront OBJ: v and f lines, 1-based indices.
void writeObj(Output& out, const TriMesh& mesh) {
  out.raw("# written by elastica\n");
  for (const Vec3& p : mesh.positions) {
    out.text("v %.*g %.*g %.*g\n", kExactDigits, p[0], kExactDigits, p[1], kExactDigits, p[2]);
    out.endRow();
  }
  for (const Face& t : mesh.faces) {
    out.text("f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1);
    out.endRow();
  }
}

// STL, one facet per face with its unit normal (zero for a degenerate face); binary corners are
// float32, as the format has them.
void writeStl(Output& out, const TriMesh& mesh, bool binary) {
  if (binary) {
    // Padded with NULs, not spaces: vcglib's STL importer (MeshLab 2020.09's) reads the label as
    // a C string, and a label without a NUL makes it read past its 80-byte buffer (AddressSanitizer
    // in io_tests).
    std::string label = "elastica binary STL";
    label.resize(80, '\0');
    out.raw(label);
    out.binary(static_cast<std::uint32_t>(mesh.faces.size()));
  } else {
    out.raw("solid elastica\n");
  }
  for (const Face& t : mesh.faces) {
    const Vec3 &p0 = mesh.positions[t[0]], &p1 = mesh.positions[t[1]], &p2 = mesh.positions[t[2]];
    Vec3 n = (p1 - p0).cross(p2 - p0);
    const double length = n.norm();
    if (length > 0) n /= length;
    if (binary) {
      for (const Vec3* p : std::array<const Vec3*, 4>{&n, &p0, &p1, &p2})
        for (int k = 0; k < 3; ++k) out.binary(static_cast<float>((*p)[k]));
      out.binary(std::uint16_t{0});
    } else {
      out.text("facet normal %.9g %.9g %.9g\n outer loop\n", n[0], n[1], n[2]);
      for (const Vec3* p : std::array<const Vec3*, 3>{&p0, &p1, &p2})
        out.text("  vertex %.*g %.*g %.*g\n", kExactDigits, (*p)[0], kExactDigits, (*p)[1], kExactDigits, (*p)[2]);
      out.raw(" endloop\nendfacet\n");
    }
    out.endRow();
  }
  if (!binary) out.raw("endsolid elastica\n");
}

void checkAttributes(const std::string& path, const TriMesh& mesh, const PlyAttributes& a) {
  const size_t nv = mesh.positions.size(), nf = mesh.faces.size();
  checkLength(path, a.vertexNormals, nv, "the vertex normals");
  checkLength(path, a.vertexColors, nv, "the vertex colours");
  checkLength(path, a.vertexQuality, nv, "the vertex quality");
  for (const PlyFloatProperty& p : a.vertexFloats) {
    if (!p.values) throw IoError(path + ": vertex property " + p.name + " has no values; nothing written");
    checkLength(path, p.values, nv, "vertex property " + p.name);
  }
  checkLength(path, a.faceFlags, nf, "the face flags");
  for (const PlyFloatProperty& p : a.faceFloats) {
    if (!p.values) throw IoError(path + ": face property " + p.name + " has no values; nothing written");
    checkLength(path, p.values, nf, "face property " + p.name);
  }
  for (const Face& t : mesh.faces)
    for (int v : t)
      if (v < 0 || static_cast<size_t>(v) >= nv) throw IoError(path + ": a face refers to a vertex the mesh does not have; nothing written");
}

void write(const std::string& path, MeshFormat format, const TriMesh& mesh, const PlyAttributes& a, bool binary) {
  checkAttributes(path, mesh, a);
  writeAtomically(path, [&](const std::string& tmp) {
    Output out(path, tmp);
    switch (format) {
      case MeshFormat::Ply:
        out.raw(header(mesh, a, binary));
        writeBody(out, mesh, a, binary);
        break;
      case MeshFormat::Off: writeOff(out, mesh, a); break;
      case MeshFormat::Obj: writeObj(out, mesh); break;
      case MeshFormat::Stl: writeStl(out, mesh, binary); break;
    }
    out.close();
  });
}

}  // namespace

std::vector<std::string> writeMesh(const std::string& path, const TriMesh& mesh, const PlyAttributes& a, bool binary) {
  const MeshFormat format = formatFromExtension(path);
  write(path, format, mesh, a, binary);
  return droppedBy(format, a);
}

void writePly(const std::string& path, const TriMesh& mesh, const PlyAttributes& a, bool binary) {
  write(path, MeshFormat::Ply, mesh, a, binary);
}

}  // namespace elastica::io
