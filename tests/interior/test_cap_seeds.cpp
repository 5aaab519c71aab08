// Poles: seeds on the protecting spheres in the middle of each material's seeds there (2.5).
#include <gtest/gtest.h>

#include "interior/top_of_cube.hpp"

namespace vorocrust {
namespace {

using test::kRadius;
using test::TopOfCube;

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

}  // namespace
}  // namespace vorocrust
