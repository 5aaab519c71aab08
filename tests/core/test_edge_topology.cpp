// Edges with any number of faces, and components joined through them.
#include <gtest/gtest.h>

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
