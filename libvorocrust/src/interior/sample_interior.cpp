// Interior seeds (paper 2.5, appendix A.5): the sampler's admission of a point, the Lipschitz pass, and
// the order of the steps.
#include "interior/interior_sampler.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>

#include "refinement/ball_index.hpp"
#include "refinement/sizing_field.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust::interior {

InteriorSampler::InteriorSampler(const std::vector<Seed>& surface_seeds, const BallIndex& protecting_balls, const SizingField& sizing,
                const geometry::Box& domain, const InteriorOptions& options, const ProgressCallback& progress,
                InteriorStats& stats)
    : surface_(surface_seeds),
      protecting_(protecting_balls),
      sizing_(sizing),
      options_(options),
      progress_(progress),
      stats_(stats),
      rng_(options.seed ^ 0x1e7e510f5eedull) {
  if (surface_seeds.empty()) throw Error(Error::Kind::InvalidGeometry, "no surface seeds to grow interior seeds from");
  for (std::uint32_t i = 0; i < surface_seeds.size(); ++i) {
    surface_tree_.insert(surface_seeds[i].position, surface_seeds[i].radius, i);
  }
  const Point centre = 0.5 * (domain.lo + domain.hi);
  const Point half = 0.5 * (domain.hi - domain.lo);
  box_.lo = centre - 3 * half;
  box_.hi = centre + 3 * half;
  domain_ = domain;
}

// The seeds that shoot spokes first: all sampled ones. (The given seeds lie on the protecting
// spheres, where spokes find no room.)
std::deque<std::uint32_t> InteriorSampler::sampled_seeds() const {
  std::deque<std::uint32_t> queue;
  for (std::uint32_t i = given_; i < seeds_.size(); ++i) queue.push_back(i);
  return queue;
}

// Shrinks every seed's ball to min over the other seeds q of r_q + L |z - q|. One pass reaches
// the fixed point: the bound through a chain of seeds is never below the direct one, by the
// triangle inequality. Returns the seeds whose balls shrank, with their radii before.
//
// A sampled seed kept the condition with the surface seeds and the older seeds when it was
// admitted, and every pass since kept it, so only the seeds that came after it can bound it;
// the given seeds (the poles) were never admitted and meet all.
std::vector<std::pair<std::uint32_t, double>> InteriorSampler::enforce_lipschitz() {
  const double L = options_.lipschitz;
  std::vector<double> radii(seeds_.size());
  tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, static_cast<std::uint32_t>(seeds_.size()), 1024),
                    [&](const auto& range) {
                      for (std::uint32_t i = range.begin(); i != range.end(); ++i) {
                        const Point& z = seeds_[i].position;
                        const bool given = i < given_;
                        double r = seeds_[i].radius;
                        if (given) r = std::min(r, surface_tree_.lipschitz_bound(z, L));
                        radii[i] = interior_tree_.lipschitz_bound(z, L, given ? 0 : i + 1, r);
                      }
                    });
  std::vector<std::pair<std::uint32_t, double>> shrunk;
  for (std::uint32_t i = 0; i < seeds_.size(); ++i) {
    if (radii[i] < seeds_[i].radius) {
      shrunk.emplace_back(i, seeds_[i].radius);
      seeds_[i].radius = radii[i];
      interior_tree_.shrink(i, radii[i]);
      ++stats_.lipschitz_shrinks;
    }
  }
  return shrunk;
}

// Seeds placed by others (the poles), kept as they are.
void InteriorSampler::add_given(const std::vector<Seed>& seeds) {
  for (const Seed& s : seeds) add(s);
  given_ = static_cast<std::uint32_t>(seeds_.size());
}

// The seed a point z would be: the region of its nearest surface seed and the radius that
// keeps the balls L-Lipschitz; nothing when z lies outside the box or in a ball, of the seeds
// so far or of `placed` (seeds not yet among them).
std::optional<Seed> InteriorSampler::admit(const Point& z, const std::vector<Seed>& placed) const {
  if ((z.array() < box_.lo.array()).any() || (z.array() > box_.hi.array()).any()) return std::nullopt;
  double radius = kInfinity;
  if (inside_or_bound(interior_tree_, z, radius)) return std::nullopt;
  if (!outside_all(placed, z, options_.lipschitz, radius)) return std::nullopt;
  // The surface seeds: containment, the Lipschitz bound and the nearest one, in one search.
  const double L = options_.lipschitz;
  bool inside = false;
  double nearest = kInfinity;
  std::uint32_t nearest_seed = 0;
  surface_tree_.search(
      z,
      [&](double d2, double max_radius, std::uint32_t) {
        return !inside && (d2 < nearest || d2 < max_radius * max_radius || L * L * d2 < radius * radius);
      },
      [&](const geometry::BallTree::Sphere& s) {
        const double d2 = (s.centre - z).squaredNorm();
        if (d2 < s.radius * s.radius) inside = true;
        if (d2 < nearest) {
          nearest = d2;
          nearest_seed = s.ball;
        }
        radius = std::min(radius, s.radius + L * std::sqrt(d2));
      });
  if (inside) return std::nullopt;
  if (protecting_.covers(z, 1 + kBallClearance)) return std::nullopt;
  const std::int32_t region = surface_[nearest_seed].region;
  // The sizing bounds cells; outside seeds have none, and only close the boundary cells: their
  // radii grow at the Lipschitz rate alone (under a small max_size, the box around the input
  // filled at that size held 36 outside seeds for every interior one, 273 s of sampling for
  // 126 571 cells of sandia_OneBox at 0.02).
  if (region != kOutsideRegion) radius = std::min(radius, sizing_(z));
  return Seed{z, region, radius, region == kOutsideRegion ? SeedKind::Outside : SeedKind::Interior};
}

// Whether z lies in a ball of `tree`; if not, `bound` falls to the tree's Lipschitz bound at z.
bool InteriorSampler::inside_or_bound(const geometry::BallTree& tree, const Point& z, double& bound) const {
  const double L = options_.lipschitz;
  bool inside = false;
  tree.search(
      z,
      [&](double d2, double max_radius, std::uint32_t) {
        return !inside && (d2 < max_radius * max_radius || L * L * d2 < bound * bound);
      },
      [&](const geometry::BallTree::Sphere& s) {
        const double d2 = (s.centre - z).squaredNorm();
        if (d2 < s.radius * s.radius) inside = true;
        bound = std::min(bound, s.radius + L * std::sqrt(d2));
      });
  return inside;
}

}  // namespace vorocrust::interior

namespace vorocrust {

std::vector<Seed> sample_interior(const std::vector<Seed>& surface_seeds, const std::vector<Seed>& cap_seeds,
                                  const BallIndex& protecting_balls, const SizingField& sizing,
                                  const geometry::Box& domain, const InteriorOptions& options,
                                  const ProgressCallback& progress, InteriorStats& stats) {
  interior::InteriorSampler sampler(surface_seeds, protecting_balls, sizing, domain, options, progress, stats);
  sampler.add_given(cap_seeds);
  if (options.mode == InteriorMode::Lattice) sampler.place_lattice();
  sampler.throw_darts();
  constexpr int kMaxRounds = 20;
  std::deque<std::uint32_t> queue = sampler.sampled_seeds();
  for (int round = 0; round < kMaxRounds; ++round) {
    sampler.shoot_spokes(std::move(queue));
    const auto shrunk = sampler.enforce_lipschitz();
    if (shrunk.empty()) break;
    queue = sampler.seeds_near(shrunk);
  }
  return sampler.take();
}

}  // namespace vorocrust
