// Interior seeds (paper 2.5, A.5): the seeds of the volume away from the surface.
//
// Contract of seed_interior(seeds, balls, regions, sizing, domain, options, phases, stats):
// `seeds` holds the surface seeds; appended to it are the poles on the protecting spheres
// (cap_seeds.hpp, "cap seeds"), then the interior and outside seeds (sample_interior.hpp,
// "interior seeds"); with InteriorMode::Cvt, Lloyd iterations then move the interior seeds
// ("cvt"). Returns the poles, which the cells' repairs keep clear of.
#pragma once

#include <vector>

#include "core/phases.hpp"
#include "geometry/box_tree.hpp"
#include "interior/sample_interior.hpp"
#include "vorocrust/seeds.hpp"
#include "vorocrust/stats.hpp"

namespace vorocrust {

class BallIndex;
class RegionLocator;
class SizingField;

struct InteriorSeedOptions {
  InteriorOptions sampling;
  int cvt_iterations = 0;  // of InteriorMode::Cvt
  int threads = 0;
};

std::vector<Seed> seed_interior(std::vector<Seed>& seeds, const BallIndex& balls, const RegionLocator& regions,
                                const SizingField& sizing, const geometry::Box& domain,
                                const InteriorSeedOptions& options, Phases& phases, InteriorStats& stats);

}  // namespace vorocrust
