#include "interior/interior_seeds.hpp"

#include "interior/cap_seeds.hpp"
#include "interior/lloyd_relaxation.hpp"

namespace vorocrust {

std::vector<Seed> seed_interior(std::vector<Seed>& seeds, const BallIndex& balls, const RegionLocator& regions,
                                const SizingField& sizing, const geometry::Box& domain,
                                const InteriorSeedOptions& options, Phases& phases, InteriorStats& stats) {
  std::vector<Seed> caps = phases("cap seeds", [&] { return pole_seeds(seeds, balls, regions); });
  const std::vector<Seed> interior = phases("interior seeds", [&] {
    return sample_interior(seeds, caps, balls, sizing, domain, options.sampling, phases.progress(), stats);
  });
  seeds.insert(seeds.end(), interior.begin(), interior.end());
  if (options.sampling.mode == InteriorMode::Cvt && options.cvt_iterations > 0) {
    stats.cvt_iterations = options.cvt_iterations;
    stats.cvt_last_move = phases("cvt", [&] {
      return lloyd_relaxation(seeds, balls, options.cvt_iterations, options.threads, phases.progress());
    });
  }
  return caps;
}

}  // namespace vorocrust
