// Internal: circles protecting the segments of a 2D domain (paper 2.3, 2.6).
//
// Each corner gets a circle centred on it; along each chain, circles centred on it follow, each
// overlapping the next, their radii bounded by the sizing field and varying by at most the
// Lipschitz constant along the chain. Next to a corner, the first circle of a chain sits on the
// corner's circle and is small enough that the two meet within a third of the angle to the
// next chain there, so that the seeds where they meet stay inside the corner's wedge.
// The refinement shrinks circles until every point where two consecutive circles meet lies
// outside every other circle (by 2 %), so that each such point can be a seed (paper 2.4).
// Throws Error(InvalidGeometry) naming the place where circles would have to shrink below
// 1e-9 of the domain's size: segments that nearly touch or cross at a tiny angle.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "features/plane_chains.hpp"
#include "refinement/sizing_field.hpp"

namespace vorocrust::refinement {

struct PlaneProtection {
  std::vector<PlaneCircle> circles;
  // Per chain, its circles in order: from its start corner's to its end corner's; a loop's
  // circles in order round it, the first not repeated at the end.
  std::vector<std::vector<std::uint32_t>> along;
  // Consecutive circles along a chain, {first, second, chain}: where seeds go in pairs.
  std::vector<std::array<std::uint32_t, 3>> pairs;
  std::size_t rounds = 0;
};

PlaneProtection protect_chains(const PlanarDomain& domain, const features::PlaneFeatures& features,
                               const SizingField& sizing, double lipschitz);

// Where circles a and b meet: {left of a->b, right of it}; false when they do not cross.
bool circles_meet(const PlaneCircle& a, const PlaneCircle& b, std::array<Point2, 2>& meet);

// A circle covers a point when the point lies within this factor of its radius.
inline constexpr double kCoverMargin = 1.02;

}  // namespace vorocrust::refinement
