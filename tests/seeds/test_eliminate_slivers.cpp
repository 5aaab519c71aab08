// Seed pairs and sliver elimination on hand-made quartets (paper 2.4, Figure 8).
#include <gtest/gtest.h>

#include <numbers>

#include "ball_sites.hpp"
#include "features/strata.hpp"
#include "refinement/ball_index.hpp"
#include "seeds/eliminate_slivers.hpp"
#include "seeds/seed_pairs.hpp"
#include "test_support.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/read_mesh.hpp"
#include "vorocrust/validate.hpp"

namespace vorocrust {
namespace {

using test::site_at;

// Four balls around a nearly flat quad: the diagonal a-c is slightly shorter than b-d, so the
// two triangles through a-c are the surface and the quartet's fourth-ball coverage decides it.
void flat_quad(BallIndex& balls, double lift, double radius) {
  balls.add(site_at(Point(0, 0, 0)), radius);
  balls.add(site_at(Point(1, 0, lift)), radius);
  balls.add(site_at(Point(1.02, 1, 0)), radius);
  balls.add(site_at(Point(0, 1, lift)), radius);
}

TEST(SeedPairs, ATetrahedronOfBallsGivesFourTripletsOnce) {
  BallIndex balls;
  flat_quad(balls, 0.0, 0.9);
  const SeedPairs pairs = find_seed_pairs(balls);
  EXPECT_EQ(pairs.triplets, 4u);
  for (const SeedPair& p : pairs.uncovered) EXPECT_TRUE(p.balls[0] < p.balls[1] && p.balls[1] < p.balls[2]);
}

TEST(SeedPairs, APlanarQuartetHasNoHalfCoveredPair) {
  // Centres in one plane: a fourth ball is as near to either point of a pair, so it covers both
  // or neither.
  BallIndex balls;
  flat_quad(balls, 0.0, 0.8);
  const SeedPairs pairs = find_seed_pairs(balls);
  EXPECT_TRUE(pairs.half_covered.empty());
  EXPECT_EQ(pairs.uncovered.size(), 2u);  // the two triangles across the shorter diagonal
}

TEST(SliverElimination, ShrinkingTheChosenBallsLeavesNoHalfCoveredPair) {
  // Lifting two opposite centres makes the quartet a flat tetrahedron: a sliver.
  BallIndex balls;
  flat_quad(balls, 0.08, 0.8);
  SeedPairs pairs = find_seed_pairs(balls);
  ASSERT_FALSE(pairs.half_covered.empty());
  const BallShrinks shrinks = choose_sliver_shrinks(balls, pairs.half_covered);
  ASSERT_FALSE(shrinks.radii.empty());
  EXPECT_GT(shrinks.max_ratio, 0);
  EXPECT_LT(shrinks.max_ratio, 0.5);
  for (const auto& [ball, radius] : shrinks.radii) {
    EXPECT_LT(radius, balls[ball].radius);
    balls.shrink(ball, radius);
  }
  pairs = find_seed_pairs(balls);
  EXPECT_TRUE(pairs.half_covered.empty());
  EXPECT_EQ(pairs.uncovered.size(), 2u);  // Figure 8: two facets, no Steiner vertex
}

// The guard on the rounds is a refusal that names a face and a place, never an internal error: a
// plugin's user must learn what to change. cgal_joint's first balls hold 368 half-covered pairs,
// so a guard of no round at all trips at once.
TEST(SliverElimination, TheGuardOnRoundsRefusesNamingTheFace) {
  SurfaceMesh mesh = read_mesh(test::model("cgal_joint.off"));
  (void)validate(mesh);
  const Strata strata = detect_strata(mesh, 30 * std::numbers::pi / 180);
  const SizingField sizing;
  RefinementOptions refinement_options;
  refinement_options.sharp_angle = 30 * std::numbers::pi / 180;
  RefinementStats refinement_stats;
  const ProgressCallback progress;
  BallRefinement refinement(mesh, strata, sizing, refinement_options, progress, refinement_stats);
  refinement.run();
  SliverOptions options;
  options.max_iterations = 0;
  SliverStats stats;
  try {
    (void)eliminate_slivers(refinement, options, progress, stats);
    FAIL() << "the guard did not trip";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::InvalidGeometry) << e.what();
    EXPECT_TRUE(e.where().face.has_value()) << e.what();
    EXPECT_NE(e.message().find("half-covered seed pairs are left, the first near ("), std::string::npos) << e.what();
    EXPECT_NE(e.message().find("--seed"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vorocrust
