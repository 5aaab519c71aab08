// A linear program in at most four unknowns: maximise objective . x subject to half-spaces
// a . x <= b and the box |x_i| <= bound, by Seidel's incremental algorithm over the half-spaces
// in the order given. Its expected work is linear in their number for a random order
// (fixed_shuffle.hpp keeps that reproducible); an order that puts the half-spaces likely to
// bound the optimum first is faster still, as then the later ones seldom move it.
//
// Tolerances are absolute, for coefficients and bounds of order one: scale the problem so.
// When the optimum is not unique, one of the optimal points is returned.
#pragma once

#include <array>
#include <optional>
#include <vector>

namespace vorocrust::geometry {

inline constexpr int kMaxUnknowns = 4;
using LpVector = std::array<double, kMaxUnknowns>;

struct HalfSpace {
  LpVector a{};  // the first `unknowns` entries are used
  double b = 0;
};

// The optimal point, or nothing when the half-spaces and the box have no common point.
// unknowns in 1..4; bound > 0.
std::optional<LpVector> maximise(int unknowns, const LpVector& objective, const std::vector<HalfSpace>& constraints,
                                 double bound);

}  // namespace vorocrust::geometry
