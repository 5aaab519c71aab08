// Splitting the pool's pieces: halves of a segment; four quarters of a triangle that tile it, keep
// its orientation, and grow rounder where the triangle is a sliver.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "refinement/subface.hpp"

namespace vorocrust {
namespace {

Point normal_of(const Subface& s) { return (s.corner(1) - s.corner(0)).cross(s.corner(2) - s.corner(0)); }

TEST(Subface, SegmentSplitsInHalves) {
  const Subface s = Subface::segment(Point(0, 0, 0), Point(2, 0, 0), 7);
  const auto children = s.split();
  EXPECT_DOUBLE_EQ(children[0].measure(), 1.0);
  EXPECT_DOUBLE_EQ(children[1].measure(), 1.0);
  EXPECT_EQ(children[2].measure(), 0.0);
  EXPECT_EQ(children[3].measure(), 0.0);
  for (const Subface& c : children) EXPECT_EQ(c.element, 7u);
}

// Quarters of equal area, oriented as the parent, whose corners lie in it, for well-shaped and
// sliver triangles alike; a focused piece's children are focused.
TEST(Subface, TriangleQuartersTileIt) {
  const std::array<std::array<Point, 3>, 3> triangles{{
      {Point(0, 0, 0), Point(1, 0, 0), Point(0.5, 0.8, 0)},      // nearly equilateral
      {Point(0, 0, 0), Point(10, 0, 0), Point(10, 0.3, 0.1)},    // a needle
      {Point(0, 0, 0), Point(10, 0, 0), Point(5.2, 0.05, 0.02)}  // a cap
  }};
  for (const auto& t : triangles) {
    Subface s = Subface::triangle(t[0], t[1], t[2], 3);
    s.focused = true;
    const Point n = normal_of(s);
    double total = 0;
    for (const Subface& c : s.split()) {
      EXPECT_EQ(c.corner_count(), 3);
      EXPECT_TRUE(c.focused);
      EXPECT_EQ(c.element, 3u);
      EXPECT_NEAR(c.measure(), s.measure() / 4, 1e-12 * s.measure());
      EXPECT_GT(normal_of(c).dot(n), 0);
      for (int k = 0; k < 3; ++k) {  // barycentric coordinates of the child's corners
        const Point p = c.corner(k);
        for (int e = 0; e < 3; ++e) {
          const Point& a = t[e];
          const Point& b = t[(e + 1) % 3];
          EXPECT_GE((b - a).cross(p - a).dot(n), -1e-12 * n.squaredNorm());
        }
      }
      total += c.measure();
    }
    EXPECT_NEAR(total, s.measure(), 1e-12 * s.measure());
  }
}

// Quartered through the edge midpoints, every piece of a sliver stays a sliver at half scale, and
// four levels down their reach is a sixteenth of the parent's. Halving the longest edge twice
// rounds most pieces, so that their mean reach is well below that.
TEST(Subface, SliversGrowRounder) {
  const std::array<Subface, 2> slivers{Subface::triangle(Point(0, 0, 0), Point(10, 0, 0), Point(5.2, 0.05, 0), 0),
                                       Subface::triangle(Point(0, 0, 0), Point(10, 0, 0), Point(10, 0.3, 0.1), 0)};
  for (const Subface& sliver : slivers) {
    std::vector<Subface> pieces{sliver};
    for (int level = 0; level < 4; ++level) {
      std::vector<Subface> next;
      for (const Subface& p : pieces) {
        for (const Subface& c : p.split()) next.push_back(c);
      }
      pieces = std::move(next);
    }
    ASSERT_EQ(pieces.size(), 256u);
    double total = 0;
    for (const Subface& p : pieces) total += p.circumradius(p.centroid());
    EXPECT_LT(total / 256, 0.75 * sliver.circumradius(sliver.centroid()) / 16);
  }
}

}  // namespace
}  // namespace vorocrust
