// Where three spheres meet: both points on all three spheres, mirror images across the plane of
// the centres, the first on the side the centres' triangle faces.
#include <gtest/gtest.h>

#include "seeds/sphere_triplet.hpp"

namespace vorocrust {
namespace {

TEST(SphereTriplet, PointsLieOnAllThreeSpheresOnEitherSide) {
  const Point c0(0, 0, 0), c1(1, 0.1, 0.05), c2(0.3, 0.9, -0.1);
  const double r0 = 0.8, r1 = 0.7, r2 = 0.75;
  const auto points = sphere_triplet_points(c0, r0, c1, r1, c2, r2);
  ASSERT_TRUE(points.has_value());
  const Point normal = (c1 - c0).cross(c2 - c0);
  for (const Point& g : *points) {
    EXPECT_NEAR((g - c0).norm(), r0, 1e-12);
    EXPECT_NEAR((g - c1).norm(), r1, 1e-12);
    EXPECT_NEAR((g - c2).norm(), r2, 1e-12);
  }
  EXPECT_GT(normal.dot((*points)[0] - c0), 0);
  EXPECT_LT(normal.dot((*points)[1] - c0), 0);
  // Mirror images: the midpoint lies in the plane of the centres.
  EXPECT_NEAR(normal.normalized().dot(0.5 * ((*points)[0] + (*points)[1]) - c0), 0, 1e-12);
}

TEST(SphereTriplet, SwappingTwoCentresSwapsTheSides) {
  const Point c0(0, 0, 0), c1(1, 0, 0), c2(0, 1, 0);
  const auto a = sphere_triplet_points(c0, 0.8, c1, 0.8, c2, 0.8);
  const auto b = sphere_triplet_points(c0, 0.8, c2, 0.8, c1, 0.8);
  ASSERT_TRUE(a && b);
  EXPECT_NEAR(((*a)[0] - (*b)[1]).norm(), 0, 1e-14);
  EXPECT_GT((*a)[0].z(), 0);
}

TEST(SphereTriplet, NothingWhenTheSpheresMissOrTheCentresAreCollinear) {
  // Pairwise overlapping, but the three lenses share no point.
  EXPECT_FALSE(sphere_triplet_points(Point(0, 0, 0), 0.55, Point(1, 0, 0), 0.55, Point(0.5, 0.9, 0), 0.55));
  EXPECT_FALSE(sphere_triplet_points(Point(0, 0, 0), 1, Point(1, 0, 0), 1, Point(2, 0, 0), 1));
  // Touching in one point only.
  EXPECT_FALSE(sphere_triplet_points(Point(0, 0, 0), 0.5, Point(1, 0, 0), 0.5, Point(0.5, 1, 0), 1.0));
}

}  // namespace
}  // namespace vorocrust
