// Near-twin seeds and the shrinks that part them (paper 2.4).
#include <gtest/gtest.h>

#include "ball_sites.hpp"
#include "refinement/ball_index.hpp"
#include "seeds/near_twins.hpp"

namespace vorocrust {
namespace {

using test::site_at;

// Four balls whose spheres pass near the origin: triplets (0, 1, 2) and (0, 1, 3) share balls 0
// and 1, and each has one point at the origin, `apart` from the other's, and one far away.
struct Quartet {
  BallIndex balls;
  std::vector<SeedPair> pairs;
  explicit Quartet(double apart, double radius_2 = 1.0, double radius_3 = 1.2) {
    balls.add(site_at(Point(1, 0, 0)), 1.0);
    balls.add(site_at(Point(0, 1, 0)), 1.0);
    balls.add(site_at(Point(0, 0, radius_2)), radius_2);
    balls.add(site_at(Point(-radius_3, 0, 0)), radius_3);
    pairs.push_back({{0, 1, 2}, {Point::Zero(), Point(1, 1, 1)}});
    pairs.push_back({{0, 1, 3}, {Point(apart, 0, 0), Point(-1, 1, -1)}});
  }
};

TEST(NearTwins, TheLargerUnsharedBallShrinks) {
  const Quartet q(2e-5);
  const TwinShrinks t = choose_twin_shrinks(q.balls, q.pairs);
  EXPECT_EQ(t.twins, 1u);
  ASSERT_EQ(t.shrinks.radii.size(), 1u);
  EXPECT_EQ(t.shrinks.radii[0].first, 3u) << "ball 3 (radius 1.2) is larger than ball 2 (radius 1)";
  EXPECT_DOUBLE_EQ(t.shrinks.radii[0].second, (1 - kShrinkClearance) * 1.2);
  EXPECT_NEAR(t.shrinks.max_ratio, kShrinkClearance, 1e-15);
}

TEST(NearTwins, EqualBallsChooseTheHigherIndexWhicheverPairComesFirst) {
  Quartet q(2e-5, 1.0, 1.0);
  const TwinShrinks a = choose_twin_shrinks(q.balls, q.pairs);
  std::swap(q.pairs[0], q.pairs[1]);
  const TwinShrinks b = choose_twin_shrinks(q.balls, q.pairs);
  ASSERT_EQ(a.shrinks.radii.size(), 1u);
  ASSERT_EQ(b.shrinks.radii.size(), 1u);
  EXPECT_EQ(a.shrinks.radii[0].first, 3u);
  EXPECT_EQ(b.shrinks.radii[0].first, 3u);
}

TEST(NearTwins, PointsFartherThanTheThresholdAreNotTwins) {
  // The mean radius of each triplet is about 1: kTwin of it is 1e-4.
  const Quartet q(2e-4);
  const TwinShrinks t = choose_twin_shrinks(q.balls, q.pairs);
  EXPECT_EQ(t.twins, 0u);
  EXPECT_TRUE(t.shrinks.radii.empty());
}

// Each point reaches kTwin of its own triplet's mean radius: a pair of points counts when either
// reaches the other, whichever comes first (surface_seeds drops a seed on the same rule).
TEST(NearTwins, EitherPointsReachMakesTwins) {
  // Triplet (0, 1, 3) is four times larger: its point reaches 4e-4 and the other's 1.2e-4.
  Quartet q(3e-4, 1.0, 10.0);
  const TwinShrinks a = choose_twin_shrinks(q.balls, q.pairs);
  std::swap(q.pairs[0], q.pairs[1]);
  const TwinShrinks b = choose_twin_shrinks(q.balls, q.pairs);
  EXPECT_EQ(a.twins, 1u);
  EXPECT_EQ(b.twins, 1u);
}

TEST(NearTwins, APairsOwnTwoPointsAreNeverTwins) {
  BallIndex balls;
  for (int k = 0; k < 3; ++k) balls.add(site_at(Point::Unit(k)), 1.0);
  const std::vector<SeedPair> pairs{{{0, 1, 2}, {Point::Zero(), Point(1e-6, 0, 0)}}};
  EXPECT_EQ(choose_twin_shrinks(balls, pairs).twins, 0u);
}

}  // namespace
}  // namespace vorocrust
