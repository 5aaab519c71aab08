// Internal: is a subface covered by the union of a few balls? Maximal Poisson-disk sampling
// drops a piece once it is covered; testing one ball at a time leaves a fringe of pieces that
// straddle two balls and must be split until each fits in one. These tests are exact (up to
// rounding) for a segment against any number of balls and a triangle against two balls.
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

// Whether every point of triangle abc lies in the first or the second ball.
bool triangle_covered_by_two(const Point& a, const Point& b, const Point& c, const CoverBall& first,
                             const CoverBall& second);

}  // namespace vorocrust
