// SPDX-License-Identifier: GPL-3.0-or-later
// The connectivity kernel: the faces at each vertex as corners (VertexFaces), appended to as hole
// filling appends, and the fans around a vertex (vertex_fans.h), on small meshes with known answers.
#include <elastica/shapes.h>
#include <elastica/vertex_faces.h>
#include <elastica/vertex_fans.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

using namespace elastica;

namespace {

std::vector<int> cornersOf(const VertexFaces& vf, int v) {
  const VertexFaces::CornerRange r = vf.corners(v);
  return {r.begin(), r.end()};
}

// The fans at v of `faces`, numbered as fansAt() numbers them.
std::vector<int> fansOf(const std::vector<Face>& faces, const VertexFaces& vf, int v, int& count) {
  std::vector<int> fan;
  FanScratch scratch;
  const VertexFaces::CornerRange r = vf.corners(v);
  count = fansAt(faces, r.begin(), r.size(), fan, scratch);
  return fan;
}

// A hexagon around vertex 0 (ring 1..6), face i = (0, i+1, i+2): vertex 0 interior, the ring on the
// border.
std::vector<Face> hexagon() {
  std::vector<Face> faces;
  for (int i = 0; i < 6; ++i) faces.push_back({0, 1 + i, 1 + (i + 1) % 6});
  return faces;
}

}  // namespace

TEST(VertexFaces, ListsEachVertexsCornersInIncreasingOrder) {
  const std::vector<Face> faces = hexagon();
  const VertexFaces vf(8, faces);  // vertex 7 is used by no face
  EXPECT_EQ(vf.builtVertexCount(), 8);
  EXPECT_EQ(cornersOf(vf, 0), (std::vector<int>{0, 3, 6, 9, 12, 15}));
  EXPECT_EQ(cornersOf(vf, 1), (std::vector<int>{1, 17}));  // faces 0 (slot 1) and 5 (slot 2)
  EXPECT_EQ(cornersOf(vf, 4), (std::vector<int>{8, 10}));  // faces 2 and 3
  EXPECT_TRUE(vf.corners(7).empty());
  EXPECT_EQ(vf.faces(1).copy(), (std::vector<int>{0, 5}));
  EXPECT_EQ(vf.faces(1).front(), 0);
  // The compact arrays agree with the ranges.
  for (int v = 0; v < 8; ++v) {
    std::vector<int> flat;
    for (int k = vf.offset(v); k < vf.offset(v + 1); ++k) flat.push_back(vf.corner(k));
    EXPECT_EQ(flat, cornersOf(vf, v)) << v;
  }
}

TEST(VertexFaces, EveryCornerOfATorusOnce) {
  const TriMesh m = shapes::torus(3, 1, 12, 6);
  const VertexFaces vf(m.vertexCount(), m.faces);
  std::vector<int> seen(3 * m.faces.size(), 0);
  for (int v = 0; v < m.vertexCount(); ++v) {
    const std::vector<int> corners = cornersOf(vf, v);
    EXPECT_TRUE(std::is_sorted(corners.begin(), corners.end())) << v;
    for (int c : corners) {
      EXPECT_EQ(m.faces[c / 3][c % 3], v);
      ++seen[c];
    }
  }
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
  EXPECT_EQ(faceListsOf(m)[5], vf.faces(5).copy());
}

// Hole filling's use: faces appended on built vertices and on vertices added after the build, a
// vertex's list edited, a rebuild that forgets the edits.
TEST(VertexFaces, AppendedFacesAndEditedLists) {
  std::vector<Face> faces = hexagon();
  faces.erase(faces.begin() + 5);  // open the hexagon between 6 and 1
  VertexFaces vf(7, faces);
  // Close it, then add a face on a new vertex 7 outside edge 1–2.
  faces.push_back({0, 6, 1});
  vf.addFace(5, faces[5]);
  faces.push_back({2, 1, 7});
  vf.addFace(6, faces[6]);
  EXPECT_EQ(vf.builtVertexCount(), 7);
  EXPECT_EQ(cornersOf(vf, 0), (std::vector<int>{0, 3, 6, 9, 12, 15}));
  EXPECT_EQ(vf.faces(1).copy(), (std::vector<int>{0, 5, 6}));
  EXPECT_EQ(cornersOf(vf, 7), (std::vector<int>{20}));
  EXPECT_TRUE(vf.corners(8).empty());  // beyond every vertex: none
  // The closed hexagon's centre has one fan; so has its border vertex 1.
  int count = 0;
  EXPECT_EQ(fansOf(faces, vf, 0, count), (std::vector<int>(6, 0)));
  EXPECT_EQ(count, 1);
  fansOf(faces, vf, 1, count);
  EXPECT_EQ(count, 1);
  // An edit replaces the vertex's list; the others keep theirs.
  vf.edit(1).pop_back();
  EXPECT_EQ(vf.faces(1).copy(), (std::vector<int>{0, 5}));
  EXPECT_EQ(vf.faces(2).copy(), (std::vector<int>{0, 1, 6}));
  vf.rebuild(7, hexagon());
  EXPECT_EQ(vf.faces(1).copy(), (std::vector<int>{0, 5}));
  EXPECT_TRUE(vf.corners(7).empty());
}

TEST(VertexFans, BorderVertexOfAnOpenFanHasOne) {
  std::vector<Face> faces = hexagon();
  faces.erase(faces.begin() + 2);  // a gap between 3 and 4: vertex 0 is on the border
  const VertexFaces vf(7, faces);
  int count = 0;
  EXPECT_EQ(fansOf(faces, vf, 0, count), (std::vector<int>(5, 0)));
  EXPECT_EQ(count, 1);
}

// A pinched vertex: fans numbered in order of their first corner, whatever the face order.
TEST(VertexFans, PinchedVertexHasOneFanPerWedge) {
  // Two triangles touching only at 0 (a bow-tie).
  {
    const std::vector<Face> faces{{0, 1, 2}, {0, 3, 4}};
    int count = 0;
    EXPECT_EQ(fansOf(faces, VertexFaces(5, faces), 0, count), (std::vector<int>{0, 1}));
    EXPECT_EQ(count, 2);
  }
  // Three wedges at 0: {faces 0, 2} share 0–4, {1, 4} share 0–2, {3} alone; vertex 4's faces are one fan.
  const std::vector<Face> faces{{0, 3, 4}, {1, 2, 0}, {4, 5, 0}, {0, 6, 7}, {0, 2, 8}};
  const VertexFaces vf(9, faces);
  int count = 0;
  EXPECT_EQ(fansOf(faces, vf, 0, count), (std::vector<int>{0, 1, 0, 2, 1}));
  EXPECT_EQ(count, 3);
  fansOf(faces, vf, 4, count);
  EXPECT_EQ(count, 1);
  // The same faces listed from the other end: numbering follows the list.
  const std::vector<int> reversed{3 * 4 + 0, 3 * 3 + 0, 3 * 2 + 2, 3 * 1 + 2, 3 * 0 + 0};
  std::vector<int> fan;
  FanScratch scratch;
  EXPECT_EQ(fansAt(faces, reversed.data(), reversed.size(), fan, scratch), 3);
  EXPECT_EQ(fan, (std::vector<int>{0, 1, 2, 0, 2}));
}

TEST(VertexFans, FanJoinNumbersByFirstMember) {
  FanJoin join;
  join.reset(6);
  join.join(5, 2);
  join.join(3, 1);
  join.join(1, 5);
  std::vector<int> fan;
  EXPECT_EQ(join.number(fan), 3);
  EXPECT_EQ(fan, (std::vector<int>{0, 1, 1, 1, 2, 1}));
  join.reset(2);  // reused: each its own fan again
  EXPECT_EQ(join.number(fan), 2);
  EXPECT_EQ(fan, (std::vector<int>{0, 1}));
}

TEST(VertexFaces, CornerAtFindsTheVertexsSlot) {
  EXPECT_EQ(cornerAt(4, {7, 8, 9}, 7), 12);
  EXPECT_EQ(cornerAt(4, {7, 8, 9}, 9), 14);
}
