// The angle between a face and the link across it: exactly known on two boxes whose seeds are
// set off from their centroids, zero against the seeds for Voronoi cells whatever their shape,
// and the mesh's figures the largest and mean of its faces'.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cells/seed_sets.hpp"
#include "vorocrust/cell_quality.hpp"
#include "vorocrust/face_orthogonality.hpp"

namespace vorocrust {
namespace {

// The unit cubes [0, 1]^3 and [1, 2] x [0, 1]^2 sharing the face x = 1 (face 0, normal +x from
// cell 0 to cell 1), each with its five other faces on the boundary.
VoronoiMesh two_cubes(const Point& site0, const Point& site1) {
  VoronoiMesh m;
  for (int x = 0; x < 3; ++x)
    for (int i = 0; i < 4; ++i) m.points.emplace_back(x, i & 1, i >> 1);  // point 4 x + i
  const auto at = [](int x, int i) { return static_cast<Index>(4 * x + i); };
  const auto add = [&](std::vector<Index> polygon, std::int32_t owner, std::int32_t neighbour) {
    VoronoiFace f;
    f.points = std::move(polygon);
    f.owner = owner;
    f.neighbour = neighbour;
    m.faces.push_back(f);
    return static_cast<Index>(m.faces.size() - 1);
  };
  const Index shared = add({at(1, 0), at(1, 1), at(1, 3), at(1, 2)}, 0, 1);  // normal +x
  for (int c = 0; c < 2; ++c) {
    VoronoiCell cell;
    cell.site = c == 0 ? site0 : site1;
    cell.centroid = Point(0.5 + c, 0.5, 0.5);
    cell.volume = 1;
    cell.region = 1;
    cell.faces = {shared};
    const int lo = c, hi = c + 1;
    if (c == 0) cell.faces.push_back(add({at(lo, 0), at(lo, 2), at(lo, 3), at(lo, 1)}, 0, kNoCell));  // x = 0
    if (c == 1) cell.faces.push_back(add({at(hi, 0), at(hi, 1), at(hi, 3), at(hi, 2)}, 1, kNoCell));  // x = 2
    cell.faces.push_back(add({at(lo, 0), at(hi, 0), at(hi, 2), at(lo, 2)}, c, kNoCell));              // y = 0
    cell.faces.push_back(add({at(lo, 1), at(lo, 3), at(hi, 3), at(hi, 1)}, c, kNoCell));              // y = 1
    cell.faces.push_back(add({at(lo, 0), at(lo, 1), at(hi, 1), at(hi, 0)}, c, kNoCell));              // z = 0
    cell.faces.push_back(add({at(lo, 2), at(hi, 2), at(hi, 3), at(lo, 3)}, c, kNoCell));              // z = 1
    m.cells.push_back(cell);
  }
  return m;
}

TEST(FaceOrthogonality, KnownAnglesOnTwoCubes) {
  // Seeds set off across the face by one unit and along it by one: the link turns 45 degrees
  // from the face's normal; the centroids' link is the normal itself.
  VoronoiMesh m = two_cubes(Point(0.5, 0.5, 0.5), Point(1.5, 1.5, 0.5));
  EXPECT_NEAR(link_angle(m, 0), 45, 1e-12);
  EXPECT_NEAR(centroid_non_orthogonality(m, 0), 0, 1e-12);
  // By 30 degrees, a tiny angle (which the cosine alone would round to 0) and none.
  m.cells[1].site = Point(1.5, 0.5 + 1 / std::sqrt(3.0), 0.5);
  EXPECT_NEAR(link_angle(m, 0), 30, 1e-12);
  m.cells[1].site = Point(1.5, 0.5 + 1e-9, 0.5);
  const double tiny = 1e-9 * 180 / std::numbers::pi;
  EXPECT_NEAR(link_angle(m, 0), tiny, 1e-6 * tiny);  // 0.5 + 1e-9 rounds in its 8th digit
  m.cells[1].site = Point(1.5, 0.5, 0.5);
  EXPECT_EQ(link_angle(m, 0), 0);
  // A face listed the wrong way round faces away from the link.
  std::reverse(m.faces[0].points.begin(), m.faces[0].points.end());
  EXPECT_NEAR(link_angle(m, 0), 180, 1e-12);
  EXPECT_NEAR(centroid_non_orthogonality(m, 0), 180, 1e-12);
  // Faces with a cell on one side only have no link.
  for (std::size_t f = 1; f < m.faces.size(); ++f) {
    EXPECT_EQ(link_angle(m, f), 0);
    EXPECT_EQ(centroid_non_orthogonality(m, f), 0);
  }
}

TEST(FaceOrthogonality, VoronoiFacesAreOrthogonalToTheirSeedLinks) {
  // Jittered seeds: the cells' centroids leave their seeds, their faces stay orthogonal to the
  // seed links.
  const auto seeds = test::lattice_seeds(10, 0.4, test::ball_region(Point(4.5, 4.5, 4.5), 3.6), 3);
  const VoronoiMesh mesh = compute_cells(seeds);
  double largest_link = 0, largest_centroid = 0, cosine_sum = 0;
  std::size_t interior = 0;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const double link = link_angle(mesh, f), centroid = centroid_non_orthogonality(mesh, f);
    largest_link = std::max(largest_link, link);
    largest_centroid = std::max(largest_centroid, centroid);
    if (mesh.faces[f].neighbour == kNoCell) continue;
    ++interior;
    cosine_sum += std::cos(centroid * std::numbers::pi / 180);
  }
  ASSERT_GT(interior, 1000u);
  EXPECT_LT(largest_link, 1e-6);
  EXPECT_GT(largest_centroid, 5);
  const CellQuality q = measure_cell_quality(mesh);
  EXPECT_EQ(q.max_link_angle, largest_link);
  EXPECT_EQ(link_angle(mesh, q.link_angle_face), largest_link);
  EXPECT_EQ(q.max_non_orthogonality, largest_centroid);
  EXPECT_NEAR(q.mean_non_orthogonality, std::acos(cosine_sum / static_cast<double>(interior)) * 180 / std::numbers::pi,
              1e-9);
  EXPECT_GT(q.mean_non_orthogonality, 0.5);
  EXPECT_LT(q.mean_non_orthogonality, largest_centroid);
}

}  // namespace
}  // namespace vorocrust
