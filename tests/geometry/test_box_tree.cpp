// The bounding-volume hierarchy's nearest-item query against brute force.
#include <gtest/gtest.h>

#include <random>

#include "geometry/box_tree.hpp"
#include "geometry/closest_point.hpp"
#include "test_support.hpp"
#include "vorocrust/read_mesh.hpp"

namespace vorocrust::geometry {
namespace {

double squared_distance_to_face(const SurfaceMesh& m, std::uint32_t f, const Point& p) {
  const Triangle& t = m.triangles[f];
  return (closest_on_triangle(p, m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]) - p).squaredNorm();
}

TEST(BoxTree, NearestFaceIsTheBruteForceNearest) {
  const SurfaceMesh m = read_mesh(test::model("igl_bunny.off"));
  const BoxTree tree = face_tree(m);
  Box bounds;
  for (const Point& v : m.vertices) bounds.include(v);
  const Point margin = 0.2 * (bounds.hi - bounds.lo);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 300; ++i) {
    Point p;
    for (int k = 0; k < 3; ++k) p[k] = bounds.lo[k] - margin[k] + unit(rng) * (bounds.hi[k] - bounds.lo[k] + 2 * margin[k]);
    const auto [face, d2] = tree.nearest(p, [&](std::uint32_t f) { return squared_distance_to_face(m, f, p); });
    double brute = std::numeric_limits<double>::infinity();
    for (std::uint32_t f = 0; f < m.num_faces(); ++f) brute = std::min(brute, squared_distance_to_face(m, f, p));
    ASSERT_NE(face, BoxTree::kNoItem);
    EXPECT_EQ(d2, brute) << "point " << i;
    EXPECT_EQ(d2, squared_distance_to_face(m, face, p));
  }
}

TEST(BoxTree, NearestInAnEmptyTreeIsNoItem) {
  const BoxTree tree({}, {});
  const auto [item, d2] = tree.nearest(Point::Zero(), [](std::uint32_t) { return 0.0; });
  EXPECT_EQ(item, BoxTree::kNoItem);
  EXPECT_EQ(d2, std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace vorocrust::geometry
