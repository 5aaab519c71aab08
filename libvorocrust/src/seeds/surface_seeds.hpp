// Internal: labelled surface seeds and the surface mesh they bound (paper 2.4).
#pragma once

#include <vector>

#include "seeds/locate_regions.hpp"
#include "seeds/seed_pairs.hpp"
#include "vorocrust/seeds.hpp"

namespace vorocrust {

struct SurfaceSeeds {
  std::vector<Seed> seeds;  // two per seed pair, in the pairs' order, but for near twins (one kept)
  // The Voronoi facets between the two seeds of a pair that the input surface passes between:
  // seeds of different regions, or of one region on either side of an open sheet (which splits
  // the cells there all the same). With no half-covered pair left each
  // is the triangle of the three ball centres dual to its seed pair, so the vertices are ball
  // centres: corners and crease points sit exactly on the input's features. Each face's normal
  // points to the side of the lower region index (outwards from a single material).
  SurfaceMesh surface;
};

SurfaceSeeds surface_seeds(const BallIndex& balls, const std::vector<SeedPair>& pairs, const RegionLocator& regions);

}  // namespace vorocrust
