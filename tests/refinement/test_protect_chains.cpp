// The circles of a 2D domain (paper 2.3, 2.6): consecutive circles meet, their meeting points
// lie outside every other circle, radii stay within the sizing, corners get their circles.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "features/plane_chains.hpp"
#include "refinement/protect_chains.hpp"
#include "test_support.hpp"

namespace vorocrust {
namespace {

refinement::PlaneProtection protect(const PlanarDomain& d, double max_size, features::PlaneFeatures& f) {
  f = features::find_plane_features(d, 30);
  return refinement::protect_chains(d, f, SizingField(max_size), 0.25);
}

void expect_meeting_points_uncovered(const refinement::PlaneProtection& p) {
  for (const auto& [i, j, chain] : p.pairs) {
    std::array<Point2, 2> meet;
    ASSERT_TRUE(refinement::circles_meet(p.circles[i], p.circles[j], meet));
    EXPECT_GT((p.circles[i].centre - p.circles[j].centre).norm(), 1e-3 * std::min(p.circles[i].radius, p.circles[j].radius))
        << "circles " << i << " and " << j << " nearly coincide";
    for (const Point2& m : meet) {
      for (std::size_t k = 0; k < p.circles.size(); ++k) {
        if (k == i || k == j) continue;
        ASSERT_GE((m - p.circles[k].centre).norm(), p.circles[k].radius) << "circle " << k << " covers a seed of " << i << ", " << j;
      }
    }
  }
}

TEST(ProtectChains, TheCrossSectionSettlesAtOnceWithItsMeetingPointsUncovered) {
  const PlanarDomain d = prepare_planar_domain(read_planar_domain(test::sample_2d("cross_section.poly")));
  features::PlaneFeatures f;
  const refinement::PlaneProtection p = protect(d, 0.25, f);
  EXPECT_EQ(p.rounds, 1u);
  expect_meeting_points_uncovered(p);
  for (const PlaneCircle& c : p.circles) EXPECT_LE(c.radius, 0.25);
  // A circle on every corner: the section's four, the layers' ends (4), the fault's two
  // crossings, its foot and its free end.
  EXPECT_EQ(std::count_if(p.circles.begin(), p.circles.end(), [](const PlaneCircle& c) { return c.corner; }), 12);
}

TEST(ProtectChains, ATenDegreeWedgeNeedsSmallerCirclesOnlyNearItsTip) {
  const PlanarDomain d = prepare_planar_domain(read_planar_domain(test::sample_2d("sharp_corners.poly")));
  features::PlaneFeatures f;
  const refinement::PlaneProtection p = protect(d, 0.1, f);
  expect_meeting_points_uncovered(p);
  // Along the wedge, a circle at distance s from its tip is at most about s sin(10 degrees).
  for (const PlaneCircle& c : p.circles) {
    if (c.corner || c.centre.norm() > 1.5 || c.centre.norm() < 1e-12) continue;
    const double angle = std::atan2(c.centre.y(), c.centre.x());
    if (angle > 0.2) continue;  // not on the wedge's sides
    EXPECT_LT(c.radius, c.centre.norm() * std::sin(10 * std::numbers::pi / 180) + 1e-12);
  }
}

TEST(ProtectChains, CirclesAcrossAThinChannelStayInsideIt) {
  const PlanarDomain d = read_planar_domain(test::sample_2d("thin_channel.poly"));
  features::PlaneFeatures f;
  const refinement::PlaneProtection p = protect(d, 0.1, f);
  expect_meeting_points_uncovered(p);
  for (const PlaneCircle& c : p.circles) {
    if (c.centre.x() > 1.05 && c.centre.x() < 1.45) {
      EXPECT_LT(c.radius, 0.02);
    }
  }
}

TEST(ProtectChains, SegmentsThatNearlyTouchAreRefusedNamingThePlace) {
  // Two squares 1e-12 apart along a side.
  PlanarDomain d;
  d.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {1 + 1e-12, 0}, {2, 0}, {2, 1}, {1 + 1e-12, 1}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  features::PlaneFeatures f;
  try {
    protect(prepare_planar_domain(d), 0.1, f);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::InvalidGeometry);
    EXPECT_NE(std::string(e.what()).find("come closer than the circles"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vorocrust
