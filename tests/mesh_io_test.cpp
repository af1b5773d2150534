// SPDX-License-Identifier: GPL-3.0-or-later
#include "file_helpers.h"

#include <elastica/errors.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/io/mesh_writer.h>
#include <elastica/shapes.h>
#include <elastica/vcg_adapter.h>
#include <elastica/vcg_mesh.h>

#include <gtest/gtest.h>
#include <wrap/io_trimesh/export_ply.h>
#include <wrap/io_trimesh/import_off.h>
#include <wrap/io_trimesh/import_ply.h>
#include <wrap/io_trimesh/import_stl.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

namespace elastica {
using test::ScratchDir;
using test::writeText;

namespace {

// A unit square pyramid without its base: 5 vertices, 4 triangles, with one quad variant.
const char* kPyramidObj =
    "# pyramid\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\n"
    "f 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n";

std::string errorOf(const std::string& path) {
  VcgMesh m;
  try {
    io::readMesh(path, m);
  } catch (const IoError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(MeshIo, PlyRoundTripBinaryAndAscii) {
  ScratchDir dir("ply");
  const TriMesh src = shapes::torus(3, 1, 16, 8);
  for (bool binary : {true, false}) {
    VcgMesh vm;
    fromTriMesh(src, vm);
    io::PlyWriteOptions opt;
    opt.binary = binary;
    const std::string path = dir.file(binary ? "b.ply" : "a.ply");
    io::writePly(path, vm, opt);
    VcgMesh back;
    io::readMesh(path, back);
    const TriMesh got = toTriMesh(back);
    ASSERT_EQ(got.vertexCount(), src.vertexCount());
    ASSERT_EQ(got.faces, src.faces);
    for (int v = 0; v < src.vertexCount(); ++v) {
      // Binary PLY keeps doubles exactly; ASCII keeps what the printed digits hold.
      EXPECT_NEAR((got.positions[v] - src.positions[v]).norm(), 0.0, binary ? 0.0 : 1e-6);
    }
  }
}

// This vcglib's OBJ importer drops every face touching the first vertex: ours must keep them,
// and triangulate polygons.
TEST(MeshIo, ObjKeepsFacesAtFirstVertexAndTriangulatesPolygons) {
  ScratchDir dir("obj");
  writeText(dir.file("p.obj"), kPyramidObj);
  VcgMesh m;
  io::readMesh(dir.file("p.obj"), m);
  EXPECT_EQ(m.vn, 5);
  EXPECT_EQ(m.fn, 4);
  writeText(dir.file("q.obj"), "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  const io::ReadReport r = io::readMesh(dir.file("q.obj"), m);
  EXPECT_EQ(m.fn, 2);
  EXPECT_EQ(r.polygonsTriangulated, 1);
  // v/vt/vn index forms and negative (relative) indices.
  writeText(dir.file("r.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf -3//1 -2//1 -1//1\n");
  io::readMesh(dir.file("r.obj"), m);
  EXPECT_EQ(m.fn, 1);
}

TEST(MeshIo, OffAndStl) {
  ScratchDir dir("offstl");
  writeText(dir.file("p.off"), "OFF\n5 4 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n"
                               "3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n");
  VcgMesh m;
  io::readMesh(dir.file("p.off"), m);
  EXPECT_EQ(m.vn, 5);
  EXPECT_EQ(m.fn, 4);
  // ASCII STL: two triangles sharing an edge, 6 corners → 4 vertices after merging.
  writeText(dir.file("s.stl"),
            "solid s\n"
            "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nendloop\nendfacet\n"
            "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\n"
            "endsolid s\n");
  const io::ReadReport r = io::readMesh(dir.file("s.stl"), m);
  EXPECT_EQ(m.vn, 4);
  EXPECT_EQ(m.fn, 2);
  EXPECT_EQ(r.duplicateVerticesMerged, 2);
}

// `writeMesh` writes the format the extension names, read back by vcglib's importers (OBJ by ours:
// this vcglib's OBJ importer drops faces, see mesh_reader.h); what a format cannot hold is named.
// The exact digits of the text formats and STL's facet normals are checked by Python's parsing
// (python/tests/test_output_formats.py).
TEST(MeshIo, WritesTheFormatItsExtensionNames) {
  ScratchDir dir("formats");
  const TriMesh src = shapes::torus(3, 1, 12, 6);
  const std::vector<double> quality(src.positions.size(), 0.5);
  const std::vector<std::array<std::uint8_t, 4>> colours(src.positions.size(), {10, 20, 30, 255});
  const std::vector<float> isNew(src.faces.size(), 1.0f);
  io::PlyAttributes a;
  a.vertexQuality = &quality;
  a.vertexColors = &colours;
  a.faceFloats = {{"elastica_new", &isNew}};
  using Dropped = std::vector<std::string>;
  auto corner = [](const VcgMesh& m, int f, int k) {
    const auto& p = m.face[f].cV(k)->cP();
    return Vec3(p[0], p[1], p[2]);
  };
  // Face f's corners as read, against the source's.
  auto sameCorners = [&](const VcgMesh& m, double tolerance) {
    if (m.fn != src.faceCount()) return false;
    for (int f = 0; f < m.fn; ++f)
      for (int k = 0; k < 3; ++k)
        if ((corner(m, f, k) - src.positions[src.faces[f][k]]).norm() > tolerance) return false;
    return true;
  };
  namespace vio = vcg::tri::io;
  int mask = 0;

  EXPECT_EQ(io::writeMesh(dir.file("t.ply"), src, a, true), Dropped{});
  VcgMesh ply;
  ASSERT_EQ(vio::ImporterPLY<VcgMesh>::Open(ply, dir.file("t.ply").c_str(), mask), 0);
  EXPECT_TRUE(mask & vio::Mask::IOM_VERTQUALITY);
  EXPECT_TRUE(sameCorners(ply, 0.0));

  EXPECT_EQ(io::writeMesh(dir.file("t.off"), src, a, true), (Dropped{"vertex quality", "elastica_new"}));
  VcgMesh off;
  ASSERT_EQ(vio::ImporterOFF<VcgMesh>::Open(off, dir.file("t.off").c_str(), mask), 0);
  EXPECT_EQ(off.vn, src.vertexCount());
  EXPECT_TRUE(sameCorners(off, 0.0));
  EXPECT_TRUE(mask & vio::Mask::IOM_VERTCOLOR);
  EXPECT_EQ(off.vert[3].cC(), vcg::Color4b(10, 20, 30, 255));

  const Dropped all{"vertex colours", "vertex quality", "elastica_new"};
  for (bool binary : {true, false}) {
    const std::string stl = dir.file(binary ? "b.STL" : "a.stl");  // the extension in any case
    EXPECT_EQ(io::writeMesh(stl, src, a, binary), all);
    VcgMesh m;
    ASSERT_EQ(vio::ImporterSTL<VcgMesh>::Open(m, stl.c_str(), mask), 0) << stl;
    EXPECT_EQ(m.vn, 3 * src.faceCount());  // unshared corners, as STL stores them
    EXPECT_TRUE(sameCorners(m, 1e-6)) << stl;  // float32 in binary STL; vcglib reads ASCII as float too
  }

  EXPECT_EQ(io::writeMesh(dir.file("t.obj"), src, a, true), all);
  const io::MeshFile obj = io::readMesh(dir.file("t.obj"));
  EXPECT_EQ(obj.mesh.faces, src.faces);
  for (int v = 0; v < src.vertexCount(); ++v)  // tinyobjloader reads floats
    EXPECT_NEAR((obj.mesh.positions[v] - src.positions[v]).norm(), 0.0, 1e-6);

  // An unknown extension: a clear error, nothing written.
  try {
    io::writeMesh(dir.file("t.xyz"), src, a, true);
    ADD_FAILURE() << "no error for .xyz";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown mesh file extension '.xyz'"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir.file("t.xyz")));
}

// A face selection as MeshLab saves it (the flags bit) or as a plain `selected` property.
TEST(MeshIo, PlyFaceSelectionFromFlagsOrASelectedProperty) {
  test::ScratchDir dir("io-selection");
  const std::string vertices = "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string body = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
  test::writeText(dir.file("p.ply"), "ply\nformat ascii 1.0\n" + vertices +
                                         "element face 2\nproperty list uchar int vertex_indices\nproperty uchar selected\n"
                                         "end_header\n" + body + "3 0 1 2 1\n3 0 2 3 0\n");
  test::writeText(dir.file("f.ply"), "ply\nformat ascii 1.0\n" + vertices +
                                         "element face 2\nproperty list uchar int vertex_indices\nproperty int flags\n"
                                         "end_header\n" + body + "3 0 1 2 0\n3 0 2 3 32\n");
  for (const auto& [file, selectedFace] : {std::pair{"p.ply", 0}, std::pair{"f.ply", 1}}) {
    VcgMesh m;
    const io::ReadReport r = io::readMesh(dir.file(file), m);
    EXPECT_TRUE(r.hasFaceSelection) << file;
    ASSERT_EQ(m.face.size(), 2u);
    EXPECT_TRUE(m.face[selectedFace].IsS()) << file;
    EXPECT_FALSE(m.face[1 - selectedFace].IsS()) << file;
  }
}

TEST(MeshIo, ClearErrors) {
  ScratchDir dir("errors");
  EXPECT_NE(errorOf(dir.file("missing.ply")).find("no such file"), std::string::npos);
  std::filesystem::create_directory(dir.file("d.ply"));
  EXPECT_NE(errorOf(dir.file("d.ply")).find("is a directory"), std::string::npos);
  writeText(dir.file("m.xyz"), "1 2 3\n");
  EXPECT_NE(errorOf(dir.file("m.xyz")).find("unknown mesh file extension"), std::string::npos);
  writeText(dir.file("e.ply"), "");
  EXPECT_NE(errorOf(dir.file("e.ply")).find("empty file"), std::string::npos);
  writeText(dir.file("g.ply"), std::string("\x7f\x45\x4c\x46 binary garbage \x01\x02\x03", 24));
  EXPECT_NE(errorOf(dir.file("g.ply")).find("malformed PLY"), std::string::npos);
  writeText(dir.file("n.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                               "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                               "0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n");
  EXPECT_NE(errorOf(dir.file("n.ply")).find("non-finite"), std::string::npos);
  writeText(dir.file("i.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
  EXPECT_FALSE(errorOf(dir.file("i.obj")).empty());
  writeText(dir.file("nofaces.off"), "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
  EXPECT_NE(errorOf(dir.file("nofaces.off")).find("no triangles"), std::string::npos);
  // Every message starts with the file name.
  EXPECT_EQ(errorOf(dir.file("e.ply")).rfind(dir.file("e.ply"), 0), 0u);
}

// vcglib's PlyInfo::AddPerVertexFloatAttribute remembers the first PlyInfo of the process in a
// static: through it, only the first file written kept its curvature properties.
TEST(MeshIo, EveryWriteKeepsItsCurvatureProperties) {
  ScratchDir dir("attributes");
  for (int i = 0; i < 3; ++i) {
    VcgMesh vm;
    fromTriMesh(shapes::icosphere(1.0, 1), vm);
    const std::vector<double> H(vm.vert.size(), 1.0 + i), K(vm.vert.size(), 2.0 + i);
    storeCurvature(vm, H, K);
    io::PlyWriteOptions opt;
    opt.binary = false;
    opt.curvature = true;
    const std::string path = dir.file("c" + std::to_string(i) + ".ply");
    io::writePly(path, vm, opt);
    const test::AsciiPly ply = test::readAsciiPly(path);
    const int h = ply.column("mean_curvature"), k = ply.column("gaussian_curvature");
    ASSERT_GE(h, 0) << "write " << i;
    ASSERT_GE(k, 0) << "write " << i;
    EXPECT_EQ(ply.vertices[0][h], 1.0 + i);  // storeCurvature takes the reported H
    EXPECT_EQ(ply.vertices[0][k], 2.0 + i);
  }
}

TEST(MeshIo, OutputChecksAndAtomicWrite) {
  ScratchDir dir("out");
  VcgMesh vm;
  fromTriMesh(shapes::icosphere(1.0, 1), vm);
  EXPECT_THROW(io::checkOutputPath(dir.file("nodir/x.ply")), IoError);
  EXPECT_THROW(io::checkOutputPath(dir.path().string()), IoError);
  io::PlyWriteOptions opt;
  io::writePly(dir.file("in.ply"), vm, opt);
  EXPECT_THROW(io::checkOutputPath(dir.file("in.ply"), dir.file("in.ply")), IoError);
  EXPECT_THROW(io::checkOutputPath(dir.file("./in.ply"), dir.file("in.ply")), IoError);
  // The written file has ordinary permissions (not mkstemp's 0600) and no temporary is left.
  struct stat st {};
  ASSERT_EQ(stat(dir.file("in.ply").c_str(), &st), 0);
  EXPECT_NE(st.st_mode & S_IRGRP, 0u);
  int entries = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) entries += e.is_regular_file();
  EXPECT_EQ(entries, 1);
  // A failed write leaves the destination untouched.
  EXPECT_THROW(io::writePly(dir.file("nodir/x.ply"), vm, opt), IoError);
  EXPECT_FALSE(std::filesystem::exists(dir.file("nodir")));
}

// Our PLY writer replaced vcglib's ExporterPLY: its files must be the exporter's, byte for byte,
// for every attribute the commands write, in binary and ASCII, with values of every length
// (tiny, huge, negative: the longest %.16g text) and non-trivial flags.
TEST(MeshIo, PlyWriterMatchesVcglibExporterByteForByte) {
  ScratchDir dir("vcg-bytes");
  namespace vio = vcg::tri::io;
  VcgMesh vm;
  fromTriMesh(shapes::torus(3, 1, 12, 6), vm);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::vector<double> H, K;
  for (auto& v : vm.vert) {
    for (int k = 0; k < 3; ++k) v.P()[k] = unit(rng) * std::pow(10.0, static_cast<int>(unit(rng) * 12));
    v.N() = vcg::Point3d(unit(rng), unit(rng), -1e-300 * unit(rng));
    H.push_back(unit(rng) * 1e4);
    K.push_back(-unit(rng) * 1e-7);
  }
  storeCurvature(vm, H, K);  // quality, colours and the two float attributes
  auto isNew = vcg::tri::Allocator<VcgMesh>::GetPerFaceAttribute<float>(vm, "elastica_new");
  for (size_t f = 0; f < vm.face.size(); ++f) {
    isNew[f] = f % 3 == 0 ? 1.0f : 0.0f;
    if (f % 2) vm.face[f].SetS();
    if (f % 5 == 0) vm.face[f].SetB(0);
  }
  auto bytes = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  for (bool binary : {true, false}) {
    io::PlyWriteOptions opt;
    opt.binary = binary;
    opt.vertexQuality = opt.vertexColor = opt.vertexNormal = opt.curvature = opt.faceFlags = true;
    opt.faceFloatAttributes = {"elastica_new"};
    const std::string ours = dir.file(binary ? "ours_b.ply" : "ours_a.ply");
    io::writePly(ours, vm, opt);

    // The same request to vcglib (PlyInfo as mesh_writer.cpp built it before).
    vio::PlyInfo info;
    info.mask = vio::Mask::IOM_VERTCOORD | vio::Mask::IOM_FACEINDEX | vio::Mask::IOM_VERTQUALITY |
                vio::Mask::IOM_VERTCOLOR | vio::Mask::IOM_VERTNORMAL | vio::Mask::IOM_FACEFLAGS;
    auto add = [&](bool face, const char* name) {
      (face ? info.FaceAttrNameVec : info.VertAttrNameVec).push_back(name);
      auto& d = face ? info.FaceDescriptorVec : info.VertDescriptorVec;
      d.push_back(vcg::ply::PropDescriptor());
      d.back().elemname = face ? "face" : "vertex";
      d.back().propname = name;
      d.back().stotype1 = d.back().memtype1 = vcg::ply::T_FLOAT;
    };
    add(true, "elastica_new");
    add(false, "mean_curvature");
    add(false, "gaussian_curvature");
    const std::string theirs = dir.file(binary ? "vcg_b.ply" : "vcg_a.ply");
    ASSERT_EQ(vio::ExporterPLY<VcgMesh>::Save(vm, theirs.c_str(), binary, info), 0);
    const std::string a = bytes(ours), b = bytes(theirs);
    ASSERT_GT(b.size(), 1000u);
    EXPECT_TRUE(a == b) << (binary ? "binary" : "ascii") << ": " << a.size() << " vs " << b.size() << " bytes";
  }
}

// The TriMesh reader: positions, faces and the face selection as the file has them.
TEST(MeshIo, ReadsIntoTheCoreMeshWithTheSelection) {
  ScratchDir dir("trimesh");
  writeText(dir.file("s.ply"),
            "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
            "element face 2\nproperty list uchar int vertex_indices\nproperty int flags\nend_header\n"
            "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2 32\n3 0 2 3 0\n");
  const io::MeshFile file = io::readMesh(dir.file("s.ply"));
  ASSERT_EQ(file.mesh.vertexCount(), 4);
  EXPECT_EQ(file.mesh.faces, (std::vector<Face>{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_TRUE(file.report.hasFaceSelection);
  EXPECT_EQ(file.faceSelection, (std::vector<std::uint8_t>{1, 0}));
  // A binary file over several read buffers (1 MB each) reads back exactly.
  const TriMesh big = shapes::icosphere(1.0, 6);  // 40,962 vertices, 2.3 MB of PLY
  io::writePly(dir.file("big.ply"), big, {}, true);
  const io::MeshFile back = io::readMesh(dir.file("big.ply"));
  EXPECT_EQ(back.mesh.positions, big.positions);
  EXPECT_EQ(back.mesh.faces, big.faces);
  EXPECT_TRUE(back.faceSelection.empty());
}

// Read into a vcglib mesh with room to spare (what `elastica fill` does, so that its patches are
// appended without moving the arrays): the mesh is the file's, and appending up to the spare keeps
// every vertex and face where it was; without the spare, appending moves them.
TEST(MeshIo, ReadsIntoAVcglibMeshWithRoomToSpare) {
  ScratchDir dir("spare");
  const TriMesh sphere = shapes::icosphere(1.0, 3);  // 642 vertices, 1,280 faces
  io::writePly(dir.file("sphere.ply"), sphere, {}, true);
  for (double spare : {0.0, 0.5}) {
    VcgMesh m;
    io::readMesh(dir.file("sphere.ply"), m, spare);
    ASSERT_EQ(m.vert.size(), sphere.positions.size());
    ASSERT_EQ(m.face.size(), sphere.faces.size());
    EXPECT_EQ(toTriMesh(m).faces, sphere.faces);
    const VcgVertex* vertices = m.vert.data();
    const VcgFace* faces = m.face.data();
    vcg::tri::Allocator<VcgMesh>::AddVertices(m, m.vert.size() / 2);
    vcg::tri::Allocator<VcgMesh>::AddFaces(m, m.face.size() / 2);
    EXPECT_EQ(m.vert.data() == vertices, spare > 0) << spare;
    EXPECT_EQ(m.face.data() == faces, spare > 0) << spare;
  }
}

}  // namespace elastica

namespace elastica {

// Bow-tie vertices are split vertex by vertex, each fan after the first getting a new vertex in
// the order of its first face; the first non-manifold edge in (lower, higher) order is named, and
// orientation is checked over all edges before any split.
TEST(MeshIo, SplitsEveryFanAndNamesTheFirstBadEdge) {
  ScratchDir dir("fans");
  // Vertex 0: three fans (faces 0, 1 and 2 each alone); vertex 1: two fans (faces 0 and 3).
  writeText(dir.file("fans.off"),
            "OFF\n10 4 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n1 1 1\n-1 -1 1\n2 0 0\n2 1 0\n-2 1 0\n"
            "3 0 1 2\n3 0 3 4\n3 0 5 6\n3 1 7 8\n");
  const io::MeshFile f = io::readMesh(dir.file("fans.off"));
  EXPECT_EQ(f.report.nonManifoldVerticesSplit, 2);
  ASSERT_EQ(f.mesh.vertexCount(), 12);  // vertex 9 (unused) dropped, three copies appended
  EXPECT_EQ(f.mesh.faces, (std::vector<Face>{{0, 1, 2}, {9, 3, 4}, {10, 5, 6}, {11, 7, 8}}));
  for (int copy : {9, 10}) EXPECT_EQ(f.mesh.positions[copy], f.mesh.positions[0]);
  EXPECT_EQ(f.mesh.positions[11], f.mesh.positions[1]);

  // Edges 0-1 and 2-3 each on three faces: the message names 0 and 1.
  writeText(dir.file("edges.off"), "OFF\n8 6 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
                                   "3 2 3 4\n3 3 2 5\n3 2 3 6\n3 0 1 4\n3 1 0 5\n3 0 1 7\n");
  EXPECT_NE(errorOf(dir.file("edges.off")).find("non-manifold edge between vertices 0 and 1 (shared by 3 faces)"),
            std::string::npos)
      << errorOf(dir.file("edges.off"));
  // A bow-tie and a flipped face: orientation is refused (first bad edge 1-2), nothing is split.
  writeText(dir.file("flip.off"), "OFF\n6 3 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n-1 0 0\n0 -1 0\n"
                                  "3 0 1 2\n3 1 2 3\n3 0 4 5\n");
  EXPECT_NE(errorOf(dir.file("flip.off")).find("1 edge traversed the same way by both faces, the first between "
                                               "vertices 1 and 2"),
            std::string::npos)
      << errorOf(dir.file("flip.off"));
}

}  // namespace elastica
