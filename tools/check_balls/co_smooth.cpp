#include "check_balls/co_smooth.hpp"

#include <cmath>
#include <numbers>

namespace vorocrust::checker {
namespace {

constexpr double kCosineSlack = 1e-9;

}  // namespace

const char* to_string(CoSmoothness result) noexcept {
  switch (result) {
    case CoSmoothness::Yes: return "co-smooth";
    case CoSmoothness::LowerStratum: return "the point is on a lower-dimensional stratum";
    case CoSmoothness::OtherStratum: return "the point is on another stratum of the same dimension";
    case CoSmoothness::NotIncident: return "the point's stratum is not incident to the centre's";
    case CoSmoothness::NoDirection: return "no usable direction";
    case CoSmoothness::DirectionAngle: return "the directions turn by more than the sharp angle";
    case CoSmoothness::Position: return "the point leaves the centre's line or tangent plane";
  }
  return "?";
}

CoSmoothTest::CoSmoothTest(const Strata& strata, double sharp_angle_radians)
    : strata_(strata), cos_theta_(std::cos(sharp_angle_radians)), sin_theta_(std::sin(sharp_angle_radians)) {}

bool CoSmoothTest::position_holds(const Point& v, const Point& d, StratumType type) const {
  const double c = std::abs(v.dot(d)) / d.norm();
  return type == StratumType::Crease ? c >= cos_theta_ - kCosineSlack : c <= sin_theta_ + kCosineSlack;
}

CoSmoothness CoSmoothTest::operator()(const SurfacePoint& p, const SurfacePoint& x) const {
  if (x.position == p.position) return CoSmoothness::Yes;
  const int dp = dimension(p.stratum.type), dx = dimension(x.stratum.type);
  if (dx < dp) return CoSmoothness::LowerStratum;
  if (dx == dp) {
    if (x.stratum.index != p.stratum.index || x.stratum.index == kNone) return CoSmoothness::OtherStratum;
    if (x.stratum.type == StratumType::Corner) return CoSmoothness::Yes;
  } else if (!strata_.incident(x.stratum, p.stratum)) {
    return CoSmoothness::NotIncident;
  }
  if (x.directions.empty() || (dx == dp && p.directions.empty())) return CoSmoothness::NoDirection;
  const Point d = x.position - p.position;
  bool direction_ok = false;
  for (const Point& vx : x.directions) {
    bool aligned = dx > dp;  // across strata only the position matters
    for (const Point& vp : p.directions) aligned = aligned || vp.dot(vx) >= cos_theta_ - kCosineSlack;
    if (!aligned) continue;
    direction_ok = true;
    if (position_holds(vx, d, x.stratum.type)) return CoSmoothness::Yes;
  }
  return direction_ok ? CoSmoothness::Position : CoSmoothness::DirectionAngle;
}

double CoSmoothTest::smallest_direction_angle(const SurfacePoint& p, const SurfacePoint& x) const {
  double best = std::numbers::pi;
  for (const Point& vx : x.directions) {
    for (const Point& vp : p.directions) best = std::min(best, angle_between(vp, vx));
  }
  return best * 180 / std::numbers::pi;
}

double CoSmoothTest::position_cosine(const SurfacePoint& p, const SurfacePoint& x) const {
  const Point d = x.position - p.position;
  if (x.directions.empty() || d.isZero()) return 0;
  return std::abs(x.directions[0].dot(d)) / d.norm();
}

}  // namespace vorocrust::checker
