// Skinny surface triangles and the shrinks that let the refinement split them (paper 2.4).
#include <gtest/gtest.h>

#include <cmath>

#include "ball_sites.hpp"
#include "refinement/ball_index.hpp"
#include "seeds/skinny_triangles.hpp"
#include "test_support.hpp"

namespace vorocrust {
namespace {


SurfaceSite site(const Point& p, StratumType type = StratumType::Patch) { return test::site_at(p, type); }

SeedPair triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  return SeedPair{{a, b, c}, {Point::Zero(), Point::Zero()}};
}

// Two close balls (0.87 apart) facing a larger one in the plane z = 0: the angle at the far ball
// is 32.3 degrees with the far ball 1.5 away, 25.8 with it 1.9 away.
struct Fan {
  BallIndex balls;
  Point circumcentre;
  explicit Fan(double far, StratumType far_type = StratumType::Patch) {
    balls.add(site(Point(0, -0.435, 0)), 1.0);
    balls.add(site(Point(0, 0.435, 0)), 1.0);
    balls.add(site(Point(far, 0, 0), far_type), 1.4 * far);
    // On the x axis, as far from (far, 0) as from (0, 0.435).
    circumcentre = Point((far * far - 0.435 * 0.435) / (2 * far), 0, 0);
  }
};

TEST(SkinnyTriangles, AGoodTriangleAsksNothing) {
  Fan fan(1.5);
  const SkinnyTriangleShrinks s = choose_skinny_triangle_shrinks(fan.balls, {triangle(0, 1, 2)}, 30, test::kDeep);
  EXPECT_EQ(s.skinny, 0u);
  EXPECT_TRUE(s.shrinks.radii.empty());
}

TEST(SkinnyTriangles, TheBallsCoveringTheCircumcentreDeeplyShrinkJustEnoughToUncoverIt) {
  Fan fan(1.9);
  const SkinnyTriangleShrinks s = choose_skinny_triangle_shrinks(fan.balls, {triangle(0, 1, 2)}, 30, test::kDeep);
  EXPECT_EQ(s.skinny, 1u);
  // The circumcentre is 0.9998 from every corner: only the far ball (radius 2.66) covers it
  // deeply; the close ones (radius 1) hold it, but not within 0.866.
  ASSERT_EQ(s.shrinks.radii.size(), 1u);
  const auto [ball, radius] = s.shrinks.radii[0];
  EXPECT_EQ(ball, 2u);
  const double d = (fan.balls[2].site.position - fan.circumcentre).norm();
  EXPECT_NEAR(d, (fan.balls[0].site.position - fan.circumcentre).norm(), 1e-12);
  EXPECT_LT(test::kDeep * radius, d);         // no longer covers it deeply
  EXPECT_GT(test::kDeep * radius, 0.9 * d);   // by a small margin only
  EXPECT_NEAR(s.shrinks.max_ratio, 1 - radius / fan.balls[2].radius, 1e-12);
}

TEST(SkinnyTriangles, AngleBoundDecidesWhichTrianglesAreSkinny) {
  Fan fan(1.9);
  EXPECT_EQ(choose_skinny_triangle_shrinks(fan.balls, {triangle(0, 1, 2)}, 25, test::kDeep).skinny, 0u);
  EXPECT_EQ(choose_skinny_triangle_shrinks(fan.balls, {triangle(0, 1, 2)}, 0, test::kDeep).skinny, 0u);
}

TEST(SkinnyTriangles, TrianglesAtFeaturesAreLeftToTheProtectingBalls) {
  Fan fan(1.9, StratumType::Crease);
  const SkinnyTriangleShrinks s = choose_skinny_triangle_shrinks(fan.balls, {triangle(0, 1, 2)}, 30, test::kDeep);
  EXPECT_EQ(s.skinny, 0u);
  EXPECT_TRUE(s.shrinks.radii.empty());
}

TEST(SkinnyTriangles, ACircumcentreInAProtectingBallAsksNothing) {
  // Patch samples cannot land inside a crease ball, whatever the patch balls' radii.
  Fan fan(1.9);
  fan.balls.add(site(fan.circumcentre + Point(0, 0, 0.05), StratumType::Crease), 0.1);
  const SkinnyTriangleShrinks s = choose_skinny_triangle_shrinks(fan.balls, {triangle(0, 1, 2)}, 30, test::kDeep);
  EXPECT_EQ(s.skinny, 1u);
  EXPECT_TRUE(s.shrinks.radii.empty());
}

TEST(SkinnyTriangles, OnlyBallsOfTheTrianglesPatchesShrink) {
  // A ball of another patch (across a thin wall) covering the circumcentre deeply stays.
  Fan fan(1.9);
  SurfaceSite other = site(fan.circumcentre + Point(0, 0, 0.2));
  other.stratum = 1;
  fan.balls.add(other, 1.0);
  const SkinnyTriangleShrinks s = choose_skinny_triangle_shrinks(fan.balls, {triangle(0, 1, 2)}, 30, test::kDeep);
  ASSERT_EQ(s.shrinks.radii.size(), 1u);
  EXPECT_EQ(s.shrinks.radii[0].first, 2u);
}

TEST(SkinnyTriangles, OneBallAskedTwiceTakesTheSmallerRadius) {
  Fan fan(1.9);
  // The same triangle twice, and another skinny one (22.6 degrees at the far ball) whose
  // circumcentre lies 0.52 from the far ball, against 1.0 for the first.
  fan.balls.add(site(Point(2.9, -0.2, 0)), 1.0);
  fan.balls.add(site(Point(2.9, 0.2, 0)), 1.0);
  const auto one = choose_skinny_triangle_shrinks(fan.balls, {triangle(0, 1, 2)}, 30, test::kDeep);
  // The smaller request first: the larger one after it must not replace it.
  const auto both = choose_skinny_triangle_shrinks(fan.balls, {triangle(2, 3, 4), triangle(0, 1, 2), triangle(0, 1, 2)},
                                                   30, test::kDeep);
  EXPECT_EQ(both.skinny, 3u);
  double far_one = 0, far_both = 0;
  for (const auto& [b, r] : one.shrinks.radii) if (b == 2) far_one = r;
  for (const auto& [b, r] : both.shrinks.radii) if (b == 2) far_both = r;
  EXPECT_GT(far_one, 0);
  EXPECT_LT(far_both, far_one);
}

}  // namespace
}  // namespace vorocrust
