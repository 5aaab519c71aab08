// Poles: seeds on the protecting spheres in the middle of each material's seeds there (2.5).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "interior/cap_seeds.hpp"
#include "refinement/ball_index.hpp"
#include "seeds/locate_regions.hpp"
#include "surface_builder.hpp"

namespace vorocrust {
namespace {

constexpr double kRadius = 0.2;

// Balls centred on the top of the cube [-1, 1]^3, the inside below them, and the inner seeds
// each ball's cap holds.
struct TopOfCube {
  SurfaceMesh surface;
  BallIndex balls;
  std::vector<Seed> seeds;

  TopOfCube() {
    test::SurfaceBuilder b;
    b.box(Point(-1, -1, -1), Point(1, 1, 1));
    surface = std::move(b.mesh);
  }
  std::uint32_t ball(double x) {
    SurfaceSite site;
    site.position = Point(x, 0, 1);
    site.direction = Point(0, 0, 1);
    return balls.add(site, kRadius);
  }
  // A seed of `region` on ball b's sphere, `polar` degrees from straight down, at `azimuth`.
  void seed(std::uint32_t b, double polar, double azimuth, std::int32_t region = kInsideRegion) {
    const double t = polar * std::numbers::pi / 180, f = azimuth * std::numbers::pi / 180;
    const Point u(std::sin(t) * std::cos(f), std::sin(t) * std::sin(f), -std::cos(t));
    seeds.push_back(Seed{balls[b].site.position + kRadius * u, region, kRadius, SeedKind::Surface});
  }
  // Eight inner seeds 70 degrees from straight down: their middle is 1.15 radii from each.
  void ring(std::uint32_t b) {
    for (int k = 0; k < 8; ++k) seed(b, 70, 45 * k);
  }
  std::vector<Seed> poles() const { return pole_seeds(seeds, balls, RegionLocator(surface)); }
};

TEST(PoleSeeds, APoleSitsInTheMiddleOfARingOfSeeds) {
  TopOfCube cube;
  cube.ring(cube.ball(0));
  const std::vector<Seed> poles = cube.poles();
  ASSERT_EQ(poles.size(), 1u);
  EXPECT_LT((poles[0].position - Point(0, 0, 1 - kRadius)).norm(), 1e-12);
  EXPECT_EQ(poles[0].region, kInsideRegion);
  EXPECT_EQ(poles[0].kind, SeedKind::Cap);
  EXPECT_EQ(poles[0].radius, kRadius);
}

// A pole 0.35 radii from a seed of its material would have a spindle for a cell, squeezed
// between that seed and the ball's centre.
TEST(PoleSeeds, NoPoleBesideASeedOfItsMaterial) {
  TopOfCube cube;
  const std::uint32_t b = cube.ball(0);
  cube.ring(b);
  cube.seed(b, 20, 0);
  EXPECT_TRUE(cube.poles().empty());
}

// A seed of another material there is on the far side of a face of the pole's cell, not inside it.
TEST(PoleSeeds, ASeedOfAnotherMaterialBesideThePoleLeavesIt) {
  TopOfCube cube;
  const std::uint32_t b = cube.ball(0);
  cube.ring(b);
  cube.seed(b, 20, 0, 2);
  EXPECT_EQ(cube.poles().size(), 1u);
}

// Two balls 0.34 radii apart: their poles, as near, would make two thin cells; only the first
// is placed. 0.5 radii apart, both are.
TEST(PoleSeeds, PolesKeepApart) {
  for (const auto& [gap, expected] : {std::pair{0.34, 1u}, std::pair{0.5, 2u}}) {
    TopOfCube cube;
    cube.ring(cube.ball(0));
    cube.ring(cube.ball(gap * kRadius));
    const std::vector<Seed> poles = cube.poles();
    ASSERT_EQ(poles.size(), expected) << gap;
    EXPECT_LT((poles[0].position - Point(0, 0, 1 - kRadius)).norm(), 1e-12);
  }
}

// One cell of the inside too long: its seed and centroid.
struct OneCell {
  std::vector<Seed> seeds;
  std::vector<cells::LongCell> long_cells;
  OneCell(const Point& site, const Point& centroid) {
    seeds.push_back(Seed{site, kInsideRegion, 0.1, SeedKind::Cap});
    long_cells.push_back({0, centroid});
  }
  std::vector<Seed> splits(const TopOfCube& cube, const std::vector<Seed>& placed = {}) const {
    return aspect_split_seeds(long_cells, seeds, cube.balls, RegionLocator(cube.surface), placed);
  }
};

TEST(AspectSplitSeeds, ACellTooLongGetsASeedAtItsCentroid) {
  TopOfCube cube;
  cube.ball(0);
  const OneCell cell(Point(0, 0, 0.8), Point(0, 0, 0.5));
  const std::vector<Seed> splits = cell.splits(cube);
  ASSERT_EQ(splits.size(), 1u);
  EXPECT_EQ(splits[0].position, Point(0, 0, 0.5));
  EXPECT_EQ(splits[0].region, kInsideRegion);
  EXPECT_EQ(splits[0].kind, SeedKind::Repair);
  EXPECT_NEAR(splits[0].radius, 0.3, 1e-12);
  // Clear of the seeds placed on spheres and before.
  EXPECT_TRUE(cell.splits(cube, {Seed{Point(0, 0, 0.51), kInsideRegion, 0.2, SeedKind::Cap}}).empty());
}

// A centroid inside a ball moves to 1.15 radii from its centre, if that leaves it nearer the
// centroid than the cell's seed; a cell whose centroid is outside its material keeps its shape.
TEST(AspectSplitSeeds, ACentroidInABallIsPushedOutOrTheCellKeepsItsShape) {
  TopOfCube cube;
  cube.ball(0);
  const std::vector<Seed> pushed = OneCell(Point(0, 0, 0.4), Point(0, 0, 0.85)).splits(cube);
  ASSERT_EQ(pushed.size(), 1u);
  EXPECT_NEAR((pushed[0].position - Point(0, 0, 1 - 1.15 * kRadius)).norm(), 0, 1e-9);
  EXPECT_TRUE(OneCell(Point(0, 0, 0.79), Point(0, 0, 0.85)).splits(cube).empty());
  EXPECT_TRUE(OneCell(Point(0.5, 0, 0.9), Point(0.5, 0, 1.1)).splits(cube).empty());
}

// A small skew face between two seeds of the inside just below a large ball, 1.02 of its radius
// from its centre: pushed to 1.05 radii, a seed at the face would lie farther from it than its
// seeds, and the ball's pole would keep it a tenth of the large radius away. The seed goes at the
// face itself, just outside the sphere, spaced at the face's own scale (cgal_bones' last skew
// faces).
TEST(SkewRepairSeeds, AFaceBesideALargeBallGetsASeedJustOutsideIt) {
  TopOfCube cube;
  const std::uint32_t b = cube.ball(0);
  const Point face_centroid(0, 0, 1 - 1.02 * kRadius);
  const std::vector<Seed> seeds = {
      Seed{face_centroid - Point(0.005, 0, 0), kInsideRegion, 0.004, SeedKind::Surface},
      Seed{face_centroid + Point(0.005, 0, 0), kInsideRegion, 0.004, SeedKind::Surface}};
  cells::CutFace face;
  face.owner_seed = 0;
  face.neighbour_seed = 1;
  face.between_cells = true;
  face.geometry.centroid = face_centroid;
  face.geometry.normal = Point(1, 0, 0);
  face.geometry.area = 1e-6;
  face.owner_centroid = face_centroid - Point(0.004, 0, 0.001);
  face.neighbour_centroid = face_centroid + Point(0.004, 0, -0.001);
  const std::vector<Seed> pole = {Seed{Point(0, 0, 1 - kRadius), kInsideRegion, kRadius, SeedKind::Cap}};
  const std::vector<Seed> added = skew_repair_seeds({face}, seeds, cube.balls, RegionLocator(cube.surface), pole);
  ASSERT_EQ(added.size(), 1u);
  EXPECT_EQ(added[0].position, face_centroid);
  EXPECT_EQ(added[0].region, kInsideRegion);
  EXPECT_EQ(added[0].kind, SeedKind::Repair);
  EXPECT_GT((added[0].position - cube.balls[b].site.position).norm(), 1.005 * kRadius);
  // A face of two materials is left alone.
  std::vector<Seed> two = seeds;
  two[1].region = 2;
  EXPECT_TRUE(skew_repair_seeds({face}, two, cube.balls, RegionLocator(cube.surface), pole).empty());
}

}  // namespace
}  // namespace vorocrust
