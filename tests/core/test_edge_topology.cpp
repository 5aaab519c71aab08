// Edges with any number of faces, and components joined through them.
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "core/edge_topology.hpp"

namespace vorocrust {
namespace {

// Three triangles around the edge (0,1), plus one more hanging off triangle 0.
SurfaceMesh book() {
  SurfaceMesh m;
  m.groups.push_back({"book", ""});
  m.vertices = {Point(0, 0, 0), Point(0, 0, 1), Point(1, 0, 0), Point(0, 1, 0), Point(-1, 0, 0), Point(1, 0, 1)};
  for (Triangle t : {Triangle{0, 1, 2}, Triangle{1, 0, 3}, Triangle{0, 1, 4}, Triangle{2, 1, 5}}) m.add_triangle(t, 0);
  return m;
}

TEST(EdgeTopology, NonManifoldEdgeKeepsAllItsFaces) {
  const SurfaceMesh m = book();
  const EdgeTopology topo = build_edge_topology(m);
  EXPECT_EQ(topo.num_edges(), 9u);
  const Index spine = topo.face_edges[0][0];
  EXPECT_EQ(topo.edges[spine], (std::array<Index, 2>{0, 1}));
  EXPECT_TRUE(topo.is_non_manifold(spine));
  const auto faces = topo.faces_of(spine);
  EXPECT_EQ(std::vector<Index>(faces.begin(), faces.end()), (std::vector<Index>{0, 1, 2}));
  std::size_t boundary = 0;
  for (std::size_t e = 0; e < topo.num_edges(); ++e) boundary += topo.is_boundary(e);
  EXPECT_EQ(boundary, 7u);
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    for (Index e : topo.face_edges[f]) {
      const auto around = topo.faces_of(e);
      EXPECT_NE(std::find(around.begin(), around.end(), f), around.end());
    }
  }
}

// Edges sorted by their vertex pair, each with its faces in face order, and every face's slots
// naming them: checked against a map of the same edges, on a fan of 40 faces about vertex 0 (more
// than a vertex's few, sorted another way), four faces about vertex 13, and random faces over 12
// vertices, whose edges have up to a dozen faces. A mesh with an index past its vertices (not validated yet) gives the same.
TEST(EdgeTopology, EdgesComeInVertexOrderWithTheirFacesInFaceOrder) {
  SurfaceMesh m;
  m.groups.push_back({"mixed", ""});
  for (Index v = 0; v < 60; ++v) m.vertices.push_back(Point(v, v % 7, v % 5));
  for (Index k = 0; k < 40; ++k) m.add_triangle({0, 20 + (k * 7) % 40, 20 + (k * 7 + 1) % 40}, 0);
  std::mt19937 random(5);
  std::uniform_int_distribution<Index> vertex(1, 12);
  // A vertex with a few corners (an insertion sort's few), their other ends out of order and
  // each met by two faces.
  for (Triangle t : {Triangle{13, 17, 15}, Triangle{13, 15, 16}, Triangle{16, 13, 17}, Triangle{14, 15, 13}}) {
    m.add_triangle(t, 0);
  }
  while (m.num_faces() < 400) {
    const Triangle t{vertex(random), vertex(random), vertex(random)};
    if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) m.add_triangle(t, 0);
  }
  std::map<std::array<Index, 2>, std::vector<Index>> expected;
  for (Index f = 0; f < m.num_faces(); ++f) {
    const Triangle& t = m.triangles[f];
    for (int k = 0; k < 3; ++k) {
      expected[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}].push_back(f);
    }
  }
  SurfaceMesh unvalidated = m;
  unvalidated.vertices.resize(30);
  for (const SurfaceMesh* mesh : {&m, &unvalidated}) {
    const EdgeTopology topo = build_edge_topology(*mesh);
    ASSERT_EQ(topo.num_edges(), expected.size());
    std::size_t e = 0;
    for (const auto& [edge, faces] : expected) {
      EXPECT_EQ(topo.edges[e], edge);
      const auto got = topo.faces_of(e);
      EXPECT_EQ(std::vector<Index>(got.begin(), got.end()), faces);
      ++e;
    }
    for (Index f = 0; f < mesh->num_faces(); ++f) {
      const Triangle& t = mesh->triangles[f];
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(topo.edges[topo.face_edges[f][k]],
                  (std::array<Index, 2>{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}));
      }
    }
  }
}

TEST(EdgeTopology, ComponentsFollowTheJoinPredicate) {
  const SurfaceMesh m = book();
  const EdgeTopology topo = build_edge_topology(m);
  std::size_t count = 0;
  label_face_components(m, topo, [](std::size_t) { return true; }, count);
  EXPECT_EQ(count, 1u);
  // Joining only across manifold edges separates the three pages.
  const auto label = label_face_components(m, topo, [&](std::size_t e) { return topo.valence(e) == 2; }, count);
  EXPECT_EQ(count, 3u);
  EXPECT_EQ(label[0], label[3]);
  EXPECT_NE(label[0], label[1]);
}

TEST(EdgeTopology, EdgeDirection) {
  const Triangle t{4, 7, 9};
  EXPECT_EQ(edge_direction(t, 4, 7), 1);
  EXPECT_EQ(edge_direction(t, 7, 4), -1);
  EXPECT_EQ(edge_direction(t, 9, 4), 1);
  EXPECT_EQ(edge_direction(t, 4, 5), 0);
}

}  // namespace
}  // namespace vorocrust
