// The two spheres of the aspect ratio against brute force: every sphere through two to four of
// the points for the smallest enclosing one, every ball touching four of the planes for the
// largest inscribed one; and on the degenerate sets lattice cells give (cospherical points,
// planes all tangent to one ball).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geometry/brute_force_spheres.hpp"
#include "geometry/small_lp.hpp"
#include "geometry/spheres.hpp"

namespace vorocrust::geometry {
namespace {

Point random_direction(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Point p(g(rng), g(rng), g(rng));
  return p.normalized();
}

bool encloses(const Sphere& s, const std::vector<Point>& points) {
  for (const Point& p : points)
    if ((p - s.centre).norm() > s.radius * (1 + 1e-12)) return false;
  return true;
}

TEST(EnclosingSphere, MatchesBruteForceOnRandomPoints) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-3, 5);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Point> points(2 + trial % 12);
    for (Point& p : points) p = Point(u(rng), u(rng), 0.1 * u(rng));  // flat sets too
    const Sphere s = smallest_enclosing_sphere(points);
    ASSERT_TRUE(encloses(s, points)) << trial;
    EXPECT_NEAR(s.radius, brute_force_enclosing_radius(points), 1e-9 * s.radius) << trial;
  }
}

TEST(EnclosingSphere, CosphericalAndCoplanarPoints) {
  // The cube's corners: every four on a face are coplanar and on one circle.
  std::vector<Point> cube;
  for (int i = 0; i < 8; ++i) cube.emplace_back(2 + (i & 1), -1 + ((i >> 1) & 1), 7 + ((i >> 2) & 1));
  Sphere s = smallest_enclosing_sphere(cube);
  EXPECT_NEAR(s.radius, std::sqrt(3.0) / 2, 1e-14);
  EXPECT_NEAR((s.centre - Point(2.5, -0.5, 7.5)).norm(), 0, 1e-14);

  // Points on the unit sphere around the axis directions: the sphere itself.
  std::mt19937_64 rng(3);
  std::vector<Point> round = {Point::UnitX(), -Point::UnitX(), Point::UnitY(), -Point::UnitY(), Point::UnitZ(),
                              -Point::UnitZ()};
  for (int k = 0; k < 60; ++k) round.push_back(random_direction(rng));
  s = smallest_enclosing_sphere(round);
  EXPECT_NEAR(s.radius, 1, 1e-14);
  EXPECT_LT(s.centre.norm(), 1e-14);

  // A circle of points and one point near its plane: no huge sphere through four nearly
  // coplanar points.
  std::vector<Point> circle;
  for (int k = 0; k < 12; ++k) circle.emplace_back(std::cos(k * M_PI / 6), std::sin(k * M_PI / 6), 0);
  circle.emplace_back(0.3, 0.2, 1e-15);
  s = smallest_enclosing_sphere(circle);
  EXPECT_NEAR(s.radius, 1, 1e-14);

  EXPECT_EQ(smallest_enclosing_sphere({Point(1, 2, 3)}).radius, 0);
  EXPECT_EQ(smallest_enclosing_sphere({Point(1, 2, 3), Point(1, 2, 3)}).radius, 0);
}

TEST(EnclosingSphere, SameAnswerForAnyOrder) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point> points(40);
  for (Point& p : points) p = Point(u(rng), u(rng), u(rng));
  const Sphere a = smallest_enclosing_sphere(points);
  std::reverse(points.begin(), points.end());
  const Sphere b = smallest_enclosing_sphere(points);
  EXPECT_NEAR(a.radius, b.radius, 1e-14);
  EXPECT_LT((a.centre - b.centre).norm(), 1e-12);
}

std::vector<Plane> tangent_planes(const std::vector<Point>& normals, const Point& centre, double radius) {
  std::vector<Plane> planes;
  for (const Point& n : normals) planes.push_back({n, n.dot(centre) + radius});
  return planes;
}

TEST(InscribedBall, MatchesBruteForceOnRandomPolytopes) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> offset(0.2, 1.5);
  for (int trial = 0; trial < 100; ++trial) {
    std::vector<Plane> planes;
    for (const Point& n : {Point(1, 0, 0), Point(-1, 0, 0), Point(0, 1, 0), Point(0, -1, 0), Point(0, 0, 1),
                           Point(0, 0, -1)}) {
      planes.push_back({n, offset(rng)});
    }
    for (int k = trial % 14; k > 0; --k) planes.push_back({random_direction(rng), offset(rng)});
    const Sphere b = largest_inscribed_ball(planes, Point::Zero(), 3);
    for (const Plane& p : planes) ASSERT_LE(p.normal.dot(b.centre) + b.radius, p.offset + 1e-14) << trial;
    EXPECT_NEAR(b.radius, brute_force_inscribed_radius(planes), 1e-10) << trial;
  }
}

TEST(InscribedBall, EveryPlaneTangent) {
  // Every constraint tight at the optimum, the most degenerate program there is.
  const Point centre(10, -4, 3);
  std::vector<Point> normals = {Point::UnitX(), -Point::UnitX(), Point::UnitY(), -Point::UnitY(), Point::UnitZ(),
                                -Point::UnitZ()};
  Sphere b = largest_inscribed_ball(tangent_planes(normals, centre, 0.5), centre + Point(0.2, 0.1, -0.3), 1);
  EXPECT_NEAR(b.radius, 0.5, 1e-14);
  EXPECT_LT((b.centre - centre).norm(), 1e-13);
  std::mt19937_64 rng(8);
  for (int k = 0; k < 40; ++k) normals.push_back(random_direction(rng));
  b = largest_inscribed_ball(tangent_planes(normals, centre, 2), centre + Point(0.5, 0.5, 0.5), 3);
  EXPECT_NEAR(b.radius, 2, 1e-12);
  EXPECT_LT((b.centre - centre).norm(), 1e-11);
}

TEST(InscribedBall, NoInteriorGivesRadiusZero) {
  // A slab of width zero.
  const std::vector<Plane> flat = {{Point::UnitX(), 1}, {-Point::UnitX(), -1}, {Point::UnitY(), 1},
                                   {-Point::UnitY(), 1}, {Point::UnitZ(), 1},  {-Point::UnitZ(), 1}};
  EXPECT_EQ(largest_inscribed_ball(flat, Point(1, 0, 0), 2).radius, 0);
}

TEST(SmallLp, BoxAndInfeasible) {
  // Maximise x + y in the unit box's corner cut by x + y <= 1.5.
  HalfSpace cut;
  cut.a = {1, 1, 0, 0};
  cut.b = 1.5;
  HalfSpace x_le_1, y_le_1;
  x_le_1.a = {1, 0, 0, 0};
  x_le_1.b = 1;
  y_le_1.a = {0, 1, 0, 0};
  y_le_1.b = 1;
  const auto x = maximise(2, {1, 1, 0, 0}, {x_le_1, y_le_1, cut}, 10);
  ASSERT_TRUE(x);
  EXPECT_NEAR((*x)[0] + (*x)[1], 1.5, 1e-14);
  // x <= -1 and -x <= -1: nothing.
  HalfSpace a, b;
  a.a = {1, 0, 0, 0};
  a.b = -1;
  b.a = {-1, 0, 0, 0};
  b.b = -1;
  EXPECT_FALSE(maximise(3, {0, 0, 1, 0}, {a, b}, 10));
  // The box alone.
  const auto corner = maximise(4, {1, -1, 0, 2}, {}, 3);
  ASSERT_TRUE(corner);
  EXPECT_EQ((*corner)[0], 3);
  EXPECT_EQ((*corner)[1], -3);
  EXPECT_EQ((*corner)[3], 3);
}

}  // namespace
}  // namespace vorocrust::geometry
