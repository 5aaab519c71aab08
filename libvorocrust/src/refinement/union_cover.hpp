// Internal: is a subface covered by the union of a few balls? Maximal Poisson-disk sampling
// drops a piece once it is covered; testing one ball at a time leaves a fringe of pieces that
// straddle two or three balls and must be split until each fits in fewer. Both tests are exact
// up to rounding, for any number of balls.
#pragma once

#include <vector>

#include "refinement/subface.hpp"

namespace vorocrust {

struct CoverBall {
  Point centre;
  double radius;  // the radius that counts as covering (e.g. (1 - alpha) r for deep cover)
};

// Whether every point of segment [a, b] lies in some ball.
bool segment_covered(const Point& a, const Point& b, const std::vector<CoverBall>& balls);

// Whether every point of triangle abc lies in some ball.
bool triangle_covered(const Point& a, const Point& b, const Point& c, const std::vector<CoverBall>& balls);

}  // namespace vorocrust
