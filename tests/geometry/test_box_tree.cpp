// The bounding-volume hierarchy's nearest-item query, and the nearest face of a surface or of a
// material's boundary, against brute force.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "core/surface_measures.hpp"
#include "geometry/box_tree.hpp"
#include "geometry/closest_point.hpp"
#include "geometry/nearest_face.hpp"
#include "surface_builder.hpp"
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

// An icosphere whose upper faces part material 1 from the outside (0), whose lower faces part
// material 2 from it, and whose faces about the equator have material 1 on both sides.
TEST(NearestFace, OfAMaterialIsTheBruteForceNearestOfTheFacesThatBoundIt) {
  SurfaceMesh m = test::icosphere(3);
  m.face_regions.resize(m.num_faces());
  for (std::uint32_t f = 0; f < m.num_faces(); ++f) {
    const double z = face_centroid(m, f).z();
    m.face_regions[f] = std::abs(z) < 0.1 ? RegionPair{1, 1} : z > 0 ? RegionPair{0, 1} : RegionPair{0, 2};
  }
  const BoxTree all = face_tree(m), bounding = boundary_tree(m, 1);
  const auto of_material = [&](std::uint32_t f) { return bounds_material(m.face_regions[f], 1); };
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(-1.5, 1.5);
  for (int i = 0; i < 300; ++i) {
    const Point p(unit(rng), unit(rng), unit(rng));
    double brute = std::numeric_limits<double>::infinity(), brute_all = brute;
    for (std::uint32_t f = 0; f < m.num_faces(); ++f) {
      const double d2 = squared_distance_to_face(m, f, p);
      brute_all = std::min(brute_all, d2);
      if (m.face_regions[f] == RegionPair{0, 1}) brute = std::min(brute, d2);
    }
    const auto [face, d2] = nearest_face(all, m, p, of_material);
    ASSERT_NE(face, BoxTree::kNoItem);
    EXPECT_EQ(m.face_regions[face], (RegionPair{0, 1})) << "point " << i;
    EXPECT_EQ(d2, brute) << "point " << i;
    EXPECT_EQ(nearest_face(bounding, m, p).second, brute) << "point " << i;
    EXPECT_EQ(nearest_face(all, m, p).second, brute_all) << "point " << i;
    EXPECT_EQ((closest_on_face(m, face, p) - p).squaredNorm(), d2);
  }
  EXPECT_EQ(nearest_face(all, m, Point::Zero(), [](std::uint32_t) { return false; }).first, BoxTree::kNoItem);
}

TEST(BoxTree, NearestInAnEmptyTreeIsNoItem) {
  const BoxTree tree({}, {});
  const auto [item, d2] = tree.nearest(Point::Zero(), [](std::uint32_t) { return 0.0; });
  EXPECT_EQ(item, BoxTree::kNoItem);
  EXPECT_EQ(d2, std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace vorocrust::geometry
