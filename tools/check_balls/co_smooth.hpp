// check_balls/co_smooth.hpp — the relaxed co-smoothness test of docs/ball-conditions.md.
//
// Contract: co_smooth(p, x) says whether the surface point x is co-smooth with the ball centre p:
// x == p; or the same crease or patch, an angle of at most theta between a direction of p and a
// direction of x, and the position test; or x on a higher stratum incident to p's, and the
// position test. The position test with d = x - p: on a crease |cos(v_x, d)| >= cos(theta), on a
// patch |cos(v_x, d)| <= sin(theta). A point on several faces or edges of its stratum carries all
// their directions and passes when any one of them does (see samples.hpp). Points on the same
// corner are co-smooth (the corner is one point; a centre off it is a protection violation).
//
// Cosines are compared with a slack of 1e-9 in the direction that passes, so that another
// implementation rounding an angle exactly at theta the other way is not called a violation.
#pragma once

#include <span>
#include <string>

#include "check_balls/strata.hpp"

namespace vorocrust::checker {

struct SurfacePoint {
  Point position;
  StratumRef stratum;
  std::span<const Point> directions;
};

enum class CoSmoothness {
  Yes,
  LowerStratum,    // x lies on a stratum of lower dimension than p's
  OtherStratum,    // another corner, crease or patch of the same dimension
  NotIncident,     // a higher stratum, but not incident to p's
  NoDirection,     // a crease or patch point without a usable direction
  DirectionAngle,  // same stratum, but the directions turn by more than theta
  Position,        // x - p leaves the crease's line or the patch's tangent plane
};

const char* to_string(CoSmoothness result) noexcept;

class CoSmoothTest {
 public:
  CoSmoothTest(const Strata& strata, double sharp_angle_radians);

  CoSmoothness operator()(const SurfacePoint& p, const SurfacePoint& x) const;

  // For messages: the smallest angle between a direction of p and of x, in degrees.
  double smallest_direction_angle(const SurfacePoint& p, const SurfacePoint& x) const;
  // For messages: |cos| between x - p and x's first direction.
  double position_cosine(const SurfacePoint& p, const SurfacePoint& x) const;

 private:
  bool position_holds(const Point& v, const Point& d, StratumType type) const;

  const Strata& strata_;
  double cos_theta_, sin_theta_;
};

}  // namespace vorocrust::checker
