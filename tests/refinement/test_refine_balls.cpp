// The refinement on real models: protection of every corner, the conditions C3 and C4 over all
// pairs of balls, determinism, and the effect of L (paper Figure 13).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "surface_builder.hpp"
#include "test_support.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/mesher.hpp"
#include "vorocrust/read_mesh.hpp"
#include "vorocrust/validate.hpp"

namespace vorocrust {
namespace {


MeshResult balls_of(const std::string& model, double lipschitz = 0.25, std::uint64_t seed = 1) {
  SurfaceMesh mesh = read_mesh(test::model(model));
  (void)validate(mesh);
  MeshOptions options;
  options.lipschitz = lipschitz;
  options.seed = seed;
  options.stop_after = Stage::Balls;
  return generate_mesh(mesh, options);
}

void expect_pairwise_conditions(const std::vector<Ball>& balls, double lipschitz) {
  std::size_t c3 = 0, c4 = 0;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    for (std::size_t j = 0; j < balls.size(); ++j) {
      if (i == j) continue;
      const double d = (balls[i].center - balls[j].center).norm();
      if (balls[i].type == balls[j].type && balls[i].radius > (balls[j].radius + lipschitz * d) * (1 + 1e-12)) ++c3;
      if (i < j && d < test::kDeep * std::max(balls[i].radius, balls[j].radius) * (1 - 1e-12)) ++c4;
    }
  }
  EXPECT_EQ(c3, 0u) << "pairs violating C3 (Lipschitz radii within a stratum type)";
  EXPECT_EQ(c4, 0u) << "pairs violating C4 (centres at least (1 - alpha) max(r) apart)";
}

TEST(RefineBalls, CubeCornersAreProtectedExactly) {
  const SurfaceMesh cube = read_mesh(test::model("sandia_OneBox.obj"));
  const MeshResult r = balls_of("sandia_OneBox.obj");
  ASSERT_TRUE(r.refinement.converged);
  EXPECT_EQ(r.features.corners, 8u);
  EXPECT_EQ(r.refinement.balls[0], 8u);
  for (const Point& corner : cube.vertices) {
    std::size_t exact = 0;
    for (const Ball& b : r.balls) exact += b.type == StratumType::Corner && b.center == corner;
    EXPECT_EQ(exact, 1u) << corner.transpose();
  }
  // Every centre lies on the cube's surface: some coordinate is 0 or 1 (the box is [0,1]^3 or a
  // translate of it, so test against its bounding box instead).
  Eigen::AlignedBox3d box;
  for (const Point& p : cube.vertices) box.extend(p);
  for (const Ball& b : r.balls) {
    const Point lo = b.center - box.min(), hi = box.max() - b.center;
    EXPECT_NEAR(std::min(lo.minCoeff(), hi.minCoeff()), 0.0, 1e-12);
    EXPECT_GT(b.radius, 0);
  }
  expect_pairwise_conditions(r.balls, 0.25);
}

TEST(RefineBalls, JointMeetsC3AndC4AndIsReproducible) {
  const MeshResult a = balls_of("cgal_joint.off", 0.25, 7);
  ASSERT_TRUE(a.refinement.converged);
  EXPECT_EQ(a.refinement.balls[0], a.features.corners);
  expect_pairwise_conditions(a.balls, 0.25);
  const MeshResult b = balls_of("cgal_joint.off", 0.25, 7);
  ASSERT_EQ(a.balls.size(), b.balls.size());
  for (std::size_t i = 0; i < a.balls.size(); ++i) {
    ASSERT_EQ(a.balls[i].center, b.balls[i].center) << i;
    ASSERT_EQ(a.balls[i].radius, b.balls[i].radius) << i;
  }
  const MeshResult c = balls_of("cgal_joint.off", 0.25, 8);
  EXPECT_NE(c.balls.size() == a.balls.size() && c.balls.back().center == a.balls.back().center, true)
      << "another seed gives another sampling";
}

TEST(RefineBalls, SmallerLipschitzGivesMoreBalls) {
  std::size_t previous = 0;
  for (double L : {0.4, 0.25, 0.15}) {
    const MeshResult r = balls_of("sandia_bracket.obj", L);
    ASSERT_TRUE(r.refinement.converged) << L;
    expect_pairwise_conditions(r.balls, L);
    EXPECT_GT(r.balls.size(), previous) << "L = " << L;
    previous = r.balls.size();
  }
}

// Every face of the input starts as a piece awaiting darts. A pass that stopped at its first run
// of misses left most of a finely tessellated surface's pieces without a dart, and the pool then
// grew four times a level (a smoothed scan: 44 million pieces after four levels, refused as a
// refinement that cannot converge); at least a dart per piece keeps it near the face count.
TEST(RefineBalls, PoolOfAFinelyTessellatedSurfaceStaysNearItsFaceCount) {
  SurfaceMesh sphere = test::icosphere(6);  // 81 920 faces, edges about 0.03 long
  MeshOptions options;
  options.stop_after = Stage::Balls;
  options.max_size = 0.02;  // balls about the size of the faces
  const MeshResult r = generate_mesh(sphere, options);
  ASSERT_TRUE(r.refinement.converged);
  EXPECT_EQ(r.refinement.balls[0] + r.refinement.balls[1], 0u);
  std::printf("[refine] icosphere(6): %zu balls, largest pool %zu pieces\n", r.balls.size(), r.refinement.largest_pool);
  EXPECT_LE(r.refinement.largest_pool, 2 * sphere.num_faces());
  expect_pairwise_conditions(r.balls, 0.25);
}

TEST(RefineBalls, MaxSizeBoundsEveryRadius) {
  SurfaceMesh mesh = read_mesh(test::model("sandia_OneBox.obj"));
  MeshOptions options;
  options.stop_after = Stage::Balls;
  options.max_size = 0.1;
  const MeshResult r = generate_mesh(mesh, options);
  for (const Ball& b : r.balls) EXPECT_LE(b.radius, 0.1);
  EXPECT_GT(r.balls.size(), 200u);
}

TEST(RefineBalls, CancellingFromTheProgressCallbackStops) {
  SurfaceMesh mesh = read_mesh(test::model("cgal_joint.off"));
  MeshOptions options;
  options.stop_after = Stage::Balls;
  int calls = 0;
  try {
    (void)generate_mesh(mesh, options, [&](const ProgressUpdate&) { return ++calls < 5; });
    FAIL() << "not cancelled";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Cancelled);
  }
  EXPECT_EQ(calls, 5);
}

}  // namespace
}  // namespace vorocrust
