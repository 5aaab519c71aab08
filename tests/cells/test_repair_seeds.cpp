// The seeds that repair the cells: splits of cells too long, and seeds for highly skew faces.
#include <gtest/gtest.h>

#include <optional>

#include "cells/repair_seeds.hpp"
#include "interior/top_of_cube.hpp"

namespace vorocrust {
namespace {

using test::kRadius;
using test::TopOfCube;

// One cell of the inside too long: its seed, centroid and far tip (by default at the centroid,
// which leaves the split no second place to try).
struct OneCell {
  std::vector<Seed> seeds;
  std::vector<cells::LongCell> long_cells;
  OneCell(const Point& site, const Point& centroid, const std::optional<Point>& tip = std::nullopt) {
    seeds.push_back(Seed{site, kInsideRegion, 0.1, SeedKind::Cap});
    long_cells.push_back({0, centroid, tip.value_or(centroid)});
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

// A cell whose centroid lies in a ball, pushed out of which it would be farther from the centroid
// than the seed is. The split
// goes halfway on to the cell's far tip, clear of the ball.
TEST(AspectSplitSeeds, ACentroidPushedPastTheSeedGivesWayToAPointHalfwayToTheTip) {
  TopOfCube cube;
  cube.ball(0);
  const Point site(0, 0, 0.79), centroid(0.03, 0, 0.88), tip(0.45, 0, 0.85);
  ASSERT_TRUE(OneCell(site, centroid).splits(cube).empty());
  const std::vector<Seed> splits = OneCell(site, centroid, tip).splits(cube);
  ASSERT_EQ(splits.size(), 1u);
  EXPECT_EQ(splits[0].position, Point((centroid + tip) / 2));
  EXPECT_NEAR(splits[0].radius, (splits[0].position - site).norm(), 1e-12);
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
