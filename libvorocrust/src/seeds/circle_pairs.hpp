// Internal: the seeds of a 2D domain's boundary (paper 2.4, 2.6): a pair where each two
// consecutive circles of a chain meet, one seed on each side of the chain, and seeds on corner
// circles where the pairs leave wide gaps round them.
//
// The circle of a corner is empty of seeds and has the seeds of its pairs on it, so its centre is
// a Voronoi vertex they share; each pair's cells meet along the chord between the two centres.
// At a segment's free end only one pair lies on the corner circle: without a seed round the back
// its two cells would meet past the end. Gaps wider than 120 degrees get seeds spread in them,
// where no other circle covers them (kind Cap).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "refinement/protect_chains.hpp"

namespace vorocrust::seeds {

struct PlaneBoundarySeeds {
  std::vector<Seed> seeds;           // z = 0, region not yet known (0)
  std::vector<std::uint32_t> twin;   // a pair seed's partner across its chain; a cap seed itself
  std::vector<std::array<std::int32_t, 2>> on_circles;  // the circles each lies on (-1: none)
};

PlaneBoundarySeeds circle_pairs(const refinement::PlaneProtection& protection);

}  // namespace vorocrust::seeds
