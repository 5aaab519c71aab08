// Internal: the interior sampler (paper 2.5, appendix A.5) that sample_interior.hpp's contract
// describes, split along its seams: admission and the Lipschitz pass (sample_interior.cpp), the
// lattice (lattice.cpp), dart throwing (darts.cpp) and spoke darts (spokes.cpp).
#pragma once

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <limits>
#include <optional>
#include <random>
#include <span>
#include <utility>
#include <vector>

#include "core/split_mix.hpp"
#include "geometry/ball_tree.hpp"
#include "interior/sample_interior.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust {
class BallIndex;
class SizingField;
}  // namespace vorocrust

namespace vorocrust::interior {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A sphere as a spoke from z sees it: its centre less z, and the power of z, |centre - z|^2 - r^2.
// Each seed shoots a hundred spokes and more against the same spheres.
struct SpokeSphere {
  Point offset;
  double power;
  SpokeSphere(const Point& z, const Point& centre, double radius)
      : offset(centre - z), power(offset.squaredNorm() - radius * radius) {}
};

// The parameter interval (t0, t1) in which z + t d (|d| = 1) lies strictly inside a sphere; empty
// (t0 >= t1) when the line misses it.
inline std::pair<double, double> chord(const Point& d, const SpokeSphere& s) {
  const double b = d.dot(s.offset);
  const double discriminant = b * b - s.power;
  if (!(discriminant > 0)) return {0, 0};
  const double h = std::sqrt(discriminant);
  return {b - h, b + h};
}

// Whether z lies outside the balls of `seeds`; `radius` falls to their Lipschitz bound at z.
inline bool outside_all(std::span<const Seed> seeds, const Point& z, double L, double& radius) {
  for (const Seed& q : seeds) {
    const double d2 = (q.position - z).squaredNorm();
    if (d2 < q.radius * q.radius) return false;
    radius = std::min(radius, q.radius + L * std::sqrt(d2));
  }
  return true;
}

// Groups of seeds whose spokes are shot side by side, and their size, chosen among the first
// seeds of the queue (InteriorSampler::next_batch).
inline constexpr std::size_t kSpokeGroups = 16, kSpokeGroup = 16, kSpokeWindow = 2048;
// Mixed into --seed for the spokes' random streams, which differ from the darts'.
inline constexpr std::uint64_t kSpokeStreams = 0x5b0c35eedull;

// Working memory of one thread's spokes.
struct Scratch {
  std::vector<geometry::BallTree::Sphere> near;
  std::vector<SpokeSphere> around;
  std::vector<std::pair<double, std::uint32_t>> keyed;
  std::vector<std::pair<double, double>> covered, gaps;
  std::vector<std::uint32_t> balls;
};

// Seeds that shoot their spokes one after the other, and what holds them.
struct SpokeGroup {
  std::vector<std::uint32_t> seeds;
  geometry::Box box;
  double largest_radius = 0;
};

// What one group's spokes did: the seeds they placed, and how many there were.
struct SpokeWork {
  std::vector<Seed> placed;
  std::uint64_t spokes = 0;
};

class InteriorSampler {
 public:
  InteriorSampler(const std::vector<Seed>& surface_seeds, const BallIndex& protecting_balls, const SizingField& sizing,
                  const geometry::Box& domain, const InteriorOptions& options, const ProgressCallback& progress,
                  InteriorStats& stats);

  // A cubic lattice over the regions deep enough for its cells; the rest is left to random seeds.
  void place_lattice();

  // Uniform darts over the grown box until `misses` darts in a row land in a ball.
  void throw_darts();

  // A direction uniform on the unit sphere (Archimedes: the height is uniform in [-1, 1]), from
  // two uniform numbers; three normal deviates cost twice as much, a tenth of the sampler.
  static Point random_direction(SplitMix64& random);

  // Spoke darts from every seed of `queue`, and from the seeds they place, each until `misses`
  // spokes in a row find no room.
  //
  // Groups of seeds shoot their spokes side by side, a batch of groups at a time (next_batch):
  // the seeds of a group one after the other, each against the seeds as they stood when the batch
  // began and those its group placed, from its own random stream. The seeds placed are then
  // taken group by group, each checked again against those taken before it (one inside another's
  // ball is dropped, its point being covered; a nearer seed can lower its radius). Batches do not
  // depend on the number of threads, and neither do the seeds.
  void shoot_spokes(std::deque<std::uint32_t> queue);

  // The seeds that shoot spokes first: all sampled ones. (The given seeds lie on the protecting
  // spheres, where spokes find no room.)
  std::deque<std::uint32_t> sampled_seeds() const;

  // The sampled seeds whose spokes may find room the shrinking of `shrunk` (seeds and their radii
  // before) freed: their own ball shrank, or their shell of spokes, out to 2 r, meets a ball as
  // it was. The paper shoots from all seeds again; the others' spokes meet the balls they met.
  // Each seed asks a tree of the shrunk balls as they were: searched from the shrunk balls, the
  // tree of all seeds bounds its nodes by the outside seeds' large radii, and prunes little.
  std::deque<std::uint32_t> seeds_near(const std::vector<std::pair<std::uint32_t, double>>& shrunk) const;

  // Shrinks every seed's ball to min over the other seeds q of r_q + L |z - q|. One pass reaches
  // the fixed point: the bound through a chain of seeds is never below the direct one, by the
  // triangle inequality. Returns the seeds whose balls shrank, with their radii before.
  //
  // A sampled seed kept the condition with the surface seeds and the older seeds when it was
  // admitted, and every pass since kept it, so only the seeds that came after it can bound it;
  // the given seeds (the poles) were never admitted and meet all.
  std::vector<std::pair<std::uint32_t, double>> enforce_lipschitz();

  std::vector<Seed> take() { return std::move(seeds_); }

  // Seeds placed by others (the poles), kept as they are.
  void add_given(const std::vector<Seed>& seeds);

 private:
  // The seed a point z would be: the region of its nearest surface seed and the radius that
  // keeps the balls L-Lipschitz; nothing when z lies outside the box or in a ball, of the seeds
  // so far or of `placed` (seeds not yet among them).
  std::optional<Seed> admit(const Point& z, const std::vector<Seed>& placed = {}) const;

  // Whether z lies in a ball of `tree`; if not, `bound` falls to the tree's Lipschitz bound at z.
  bool inside_or_bound(const geometry::BallTree& tree, const Point& z, double& bound) const;

  // The next batch: groups of seeds from the front of the queue, such that the spokes of a
  // group and the balls they place cannot meet another group's (a spoke from z reaches 2 r_z,
  // and the ball of a seed it places at most 1.5 r_z, by the Lipschitz bound through z), so
  // that the groups place what they would one after the other. A seed joins the one group it
  // comes near, or starts one; seeds near two groups, or that find theirs full or no group left,
  // keep their places at the front. Groups of neighbours keep each thread's memory warm.
  void next_batch(std::deque<std::uint32_t>& queue, std::vector<SpokeGroup>& groups);

  // One seed's spokes, against the seeds so far and those its group placed (`out`).
  void spokes_from(std::uint32_t from, Scratch& scratch, SpokeWork& out) const;

  // Every ball that reaches within `reach` of z: seeds' balls and protecting balls.
  void gather_spheres(const Point& z, double reach, std::vector<geometry::BallTree::Sphere>& out, Scratch& scratch) const;

  // The spheres as spokes from z see them (`out`), by their distance from reaching z, equals in
  // the order given.
  static void nearest_first(const Point& z, const std::vector<geometry::BallTree::Sphere>& spheres,
                            std::vector<SpokeSphere>& out, Scratch& scratch);

  // A point of the spoke z + t d, t in [t_lo, t_hi], that none of the spheres covers and the box
  // holds, chosen uniformly (u in [0, 1)) over that part's length; nothing when no part is left.
  std::optional<double> uncovered_point(const Point& z, const Point& d, double t_lo, double t_hi, double u,
                                        const std::vector<SpokeSphere>& spheres, Scratch& scratch) const;

  void add(const Seed& seed) {
    interior_tree_.insert(seed.position, seed.radius, static_cast<std::uint32_t>(seeds_.size()));
    seeds_.push_back(seed);
    if (seed.region != kOutsideRegion && ++material_seeds_ >= next_material_report_) report_material_seeds();
  }

  // Hands options_.on_material_seeds the count, and sets the next count to report at a quarter
  // more: the reports cost nothing next to the seeds.
  void report_material_seeds() {
    next_material_report_ = material_seeds_ + std::max<std::size_t>(material_seeds_ / 4, 1024);
    if (options_.on_material_seeds) options_.on_material_seeds(material_seeds_);
  }

  void check_cancel() const {
    if (progress_ && !progress_({"interior seeds", -1})) throw Error(Error::Kind::Cancelled, "cancelled");
  }

  const std::vector<Seed>& surface_;
  const BallIndex& protecting_;
  const SizingField& sizing_;
  InteriorOptions options_;
  const ProgressCallback& progress_;
  InteriorStats& stats_;
  std::mt19937_64 rng_;
  geometry::Box box_, domain_;
  geometry::BallTree surface_tree_, interior_tree_;
  std::vector<Seed> seeds_;
  std::uint32_t given_ = 0;  // seeds_[0, given_) were given (add_given), not sampled
  std::size_t material_seeds_ = 0, next_material_report_ = 1024;
  std::vector<std::uint32_t> passed_over_;  // next_batch's
  tbb::enumerable_thread_specific<Scratch> scratch_;
};

}  // namespace vorocrust::interior
