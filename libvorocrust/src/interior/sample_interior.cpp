// Interior seeds (paper 2.5, appendix A.5).
#include "interior/sample_interior.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <span>

#include "core/split_mix.hpp"
#include "geometry/ball_tree.hpp"
#include "refinement/ball_index.hpp"
#include "refinement/sizing_field.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

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
std::pair<double, double> chord(const Point& d, const SpokeSphere& s) {
  const double b = d.dot(s.offset);
  const double discriminant = b * b - s.power;
  if (!(discriminant > 0)) return {0, 0};
  const double h = std::sqrt(discriminant);
  return {b - h, b + h};
}

// Whether z lies outside the balls of `seeds`; `radius` falls to their Lipschitz bound at z.
bool outside_all(std::span<const Seed> seeds, const Point& z, double L, double& radius) {
  for (const Seed& q : seeds) {
    const double d2 = (q.position - z).squaredNorm();
    if (d2 < q.radius * q.radius) return false;
    radius = std::min(radius, q.radius + L * std::sqrt(d2));
  }
  return true;
}

// Groups of seeds whose spokes are shot side by side, and their size, chosen among the first
// seeds of the queue (InteriorSampler::next_batch).
constexpr std::size_t kSpokeGroups = 16, kSpokeGroup = 16, kSpokeWindow = 2048;
// Mixed into --seed for the spokes' random streams, which differ from the darts'.
constexpr std::uint64_t kSpokeStreams = 0x5b0c35eedull;

// Working memory of one thread's spokes.
struct Scratch {
  std::vector<BallTree::Sphere> near;
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

  // A cubic lattice over the regions deep enough for its cells; the rest is left to random seeds.
  void place_lattice() {
    std::vector<double> radii;
    for (const Seed& s : surface_) radii.push_back(s.radius);
    std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
    const Point centre = 0.5 * (domain_.lo + domain_.hi);
    const double spacing = std::min(radii[radii.size() / 2], sizing_(centre));
    // A ball of this radius about each lattice point covers its lattice cube, so no random seed
    // lands between lattice points.
    const double radius = 0.87 * spacing;
    Eigen::Vector3i lo, hi;
    for (int k = 0; k < 3; ++k) {
      lo[k] = static_cast<int>(std::floor((domain_.lo[k] - centre[k]) / spacing));
      hi[k] = static_cast<int>(std::ceil((domain_.hi[k] - centre[k]) / spacing));
    }
    for (int i = lo[0]; i <= hi[0]; ++i) {
      for (int j = lo[1]; j <= hi[1]; ++j) {
        for (int k = lo[2]; k <= hi[2]; ++k) {
          const Point z = centre + spacing * Point(i, j, k);
          const std::optional<Seed> seed = admit(z);
          if (seed && seed->region != kOutsideRegion && seed->radius >= radius) {
            add({z, seed->region, radius, SeedKind::Interior});
            ++stats_.lattice_seeds;
          }
        }
      }
      check_cancel();
    }
  }

  // Uniform darts over the grown box until `misses` darts in a row land in a ball.
  void throw_darts() {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int misses = 0; misses < options_.misses;) {
      const Point z = box_.lo + (box_.hi - box_.lo).cwiseProduct(Point(unit(rng_), unit(rng_), unit(rng_)));
      if (const std::optional<Seed> seed = admit(z)) {
        add(*seed);
        ++stats_.darts;
        misses = 0;
      } else {
        ++misses;
      }
    }
  }

  // A direction uniform on the unit sphere (Archimedes: the height is uniform in [-1, 1]), from
  // two uniform numbers; three normal deviates cost twice as much, a tenth of the sampler.
  static Point random_direction(SplitMix64& random) {
    const double z = 2 * random.unit() - 1;
    const double phi = 2 * std::numbers::pi * random.unit();
    const double s = std::sqrt(std::max(0.0, 1 - z * z));
    return {s * std::cos(phi), s * std::sin(phi), z};
  }

  // Spoke darts from every seed of `queue`, and from the seeds they place, each until `misses`
  // spokes in a row find no room.
  //
  // Groups of seeds shoot their spokes side by side, a batch of groups at a time (next_batch):
  // the seeds of a group one after the other, each against the seeds as they stood when the batch
  // began and those its group placed, from its own random stream. The seeds placed are then
  // taken group by group, each checked again against those taken before it (one inside another's
  // ball is dropped, its point being covered; a nearer seed can lower its radius). Batches do not
  // depend on the number of threads, and neither do the seeds.
  void shoot_spokes(std::deque<std::uint32_t> queue) {
    ++stats_.rounds;
    std::vector<SpokeGroup> groups;
    std::vector<SpokeWork> work;
    while (!queue.empty()) {
      check_cancel();
      next_batch(queue, groups);
      work.assign(groups.size(), SpokeWork{});
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, groups.size(), 1), [&](const auto& range) {
        Scratch& scratch = scratch_.local();
        for (std::size_t g = range.begin(); g != range.end(); ++g) {
          for (std::uint32_t from : groups[g].seeds) spokes_from(from, scratch, work[g]);
        }
      });
      // Admitted against all seeds older than the batch, the seeds placed need checking only
      // against those taken in it.
      const std::size_t batch_start = seeds_.size();
      for (SpokeWork& w : work) {
        stats_.spokes += w.spokes;
        for (Seed& seed : w.placed) {
          const std::span<const Seed> taken(seeds_.begin() + static_cast<std::ptrdiff_t>(batch_start), seeds_.end());
          if (!outside_all(taken, seed.position, options_.lipschitz, seed.radius)) continue;
          add(seed);
          ++stats_.spoke_seeds;
          queue.push_back(static_cast<std::uint32_t>(seeds_.size() - 1));
        }
      }
    }
  }

  // The seeds that shoot spokes first: all sampled ones. (The given seeds lie on the protecting
  // spheres, where spokes find no room.)
  std::deque<std::uint32_t> sampled_seeds() const {
    std::deque<std::uint32_t> queue;
    for (std::uint32_t i = given_; i < seeds_.size(); ++i) queue.push_back(i);
    return queue;
  }

  // The sampled seeds whose spokes may find room the shrinking of `shrunk` (seeds and their radii
  // before) freed: their own ball shrank, or their shell of spokes, out to 2 r, meets a ball as
  // it was. The paper shoots from all seeds again; the others' spokes meet the balls they met.
  // Each seed asks a tree of the shrunk balls as they were: searched from the shrunk balls, the
  // tree of all seeds bounds its nodes by the outside seeds' large radii, and prunes little.
  std::deque<std::uint32_t> seeds_near(const std::vector<std::pair<std::uint32_t, double>>& shrunk) const {
    BallTree before;
    std::vector<char> near(seeds_.size(), 0);
    for (std::uint32_t k = 0; k < shrunk.size(); ++k) {
      const auto [q, old_radius] = shrunk[k];
      before.insert(seeds_[q].position, old_radius, k);
      near[q] = 1;
    }
    const auto first = static_cast<std::uint32_t>(given_);
    const auto end = static_cast<std::uint32_t>(seeds_.size());
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(first, end, 1024), [&](const auto& range) {
      for (std::uint32_t i = range.begin(); i != range.end(); ++i) {
        if (near[i]) continue;
        const Point& z = seeds_[i].position;
        const double reach = 2 * seeds_[i].radius;
        bool meets = false;
        before.search(
            z,
            [&](double d2, double max_radius, std::uint32_t) {
              return !meets && d2 < (reach + max_radius) * (reach + max_radius);
            },
            [&](const BallTree::Sphere& s) {
              meets = meets || (s.centre - z).squaredNorm() < (reach + s.radius) * (reach + s.radius);
            });
        near[i] = meets;
      }
    });
    std::deque<std::uint32_t> queue;
    for (std::uint32_t i = first; i < end; ++i) {
      if (near[i]) queue.push_back(i);
    }
    return queue;
  }

  // Shrinks every seed's ball to min over the other seeds q of r_q + L |z - q|. One pass reaches
  // the fixed point: the bound through a chain of seeds is never below the direct one, by the
  // triangle inequality. Returns the seeds whose balls shrank, with their radii before.
  //
  // A sampled seed kept the condition with the surface seeds and the older seeds when it was
  // admitted, and every pass since kept it, so only the seeds that came after it can bound it;
  // the given seeds (the poles) were never admitted and meet all.
  std::vector<std::pair<std::uint32_t, double>> enforce_lipschitz() {
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

  std::vector<Seed> take() { return std::move(seeds_); }

  // Seeds placed by others (the poles), kept as they are.
  void add_given(const std::vector<Seed>& seeds) {
    for (const Seed& s : seeds) add(s);
    given_ = static_cast<std::uint32_t>(seeds_.size());
  }

 private:
  // The seed a point z would be: the region of its nearest surface seed and the radius that
  // keeps the balls L-Lipschitz; nothing when z lies outside the box or in a ball, of the seeds
  // so far or of `placed` (seeds not yet among them).
  std::optional<Seed> admit(const Point& z, const std::vector<Seed>& placed = {}) const {
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
        [&](const BallTree::Sphere& s) {
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
    radius = std::min(radius, sizing_(z));
    const std::int32_t region = surface_[nearest_seed].region;
    return Seed{z, region, radius, region == kOutsideRegion ? SeedKind::Outside : SeedKind::Interior};
  }

  // Whether z lies in a ball of `tree`; if not, `bound` falls to the tree's Lipschitz bound at z.
  bool inside_or_bound(const BallTree& tree, const Point& z, double& bound) const {
    const double L = options_.lipschitz;
    bool inside = false;
    tree.search(
        z,
        [&](double d2, double max_radius, std::uint32_t) {
          return !inside && (d2 < max_radius * max_radius || L * L * d2 < bound * bound);
        },
        [&](const BallTree::Sphere& s) {
          const double d2 = (s.centre - z).squaredNorm();
          if (d2 < s.radius * s.radius) inside = true;
          bound = std::min(bound, s.radius + L * std::sqrt(d2));
        });
    return inside;
  }

  // The next batch: groups of seeds from the front of the queue, such that the spokes of a
  // group and the balls they place cannot meet another group's (a spoke from z reaches 2 r_z,
  // and the ball of a seed it places at most 1.5 r_z, by the Lipschitz bound through z), so
  // that the groups place what they would one after the other. A seed joins the one group it
  // comes near, or starts one; seeds near two groups, or that find theirs full or no group left,
  // keep their places at the front. Groups of neighbours keep each thread's memory warm.
  void next_batch(std::deque<std::uint32_t>& queue, std::vector<SpokeGroup>& groups) {
    constexpr double kApart = 3.5;
    groups.clear();
    passed_over_.clear();
    const auto near = [&](const Seed& s, const SpokeGroup& group) {
      const double margin = kApart * (s.radius + group.largest_radius);
      if ((s.position.array() < group.box.lo.array() - margin).any() ||
          (s.position.array() > group.box.hi.array() + margin).any()) {
        return false;
      }
      return std::any_of(group.seeds.begin(), group.seeds.end(), [&](std::uint32_t m) {
        const double reach = kApart * (s.radius + seeds_[m].radius);
        return (s.position - seeds_[m].position).squaredNorm() <= reach * reach;
      });
    };
    const std::size_t window = std::min(kSpokeWindow, queue.size());
    std::size_t k = 0, taken = 0;
    for (; k < window && taken < kSpokeGroups * kSpokeGroup; ++k) {
      const std::uint32_t i = queue[k];
      const Seed& s = seeds_[i];
      std::size_t meets = groups.size(), count = 0;
      for (std::size_t g = 0; g < groups.size() && count < 2; ++g) {
        if (near(s, groups[g])) meets = g, ++count;
      }
      if (count == 0 && groups.size() < kSpokeGroups) meets = groups.size(), groups.emplace_back();
      if (count > 1 || meets == groups.size() || groups[meets].seeds.size() == kSpokeGroup) {
        passed_over_.push_back(i);
        continue;
      }
      SpokeGroup& group = groups[meets];
      group.seeds.push_back(i);
      group.box.include(s.position);
      group.largest_radius = std::max(group.largest_radius, s.radius);
      ++taken;
    }
    queue.erase(queue.begin(), queue.begin() + static_cast<std::ptrdiff_t>(k));
    queue.insert(queue.begin(), passed_over_.begin(), passed_over_.end());
  }

  // One seed's spokes, against the seeds so far and those its group placed (`out`).
  void spokes_from(std::uint32_t from, Scratch& scratch, SpokeWork& out) const {
    SplitMix64 random = SplitMix64::stream(options_.seed ^ kSpokeStreams, (std::uint64_t{stats_.rounds} << 32) | from);
    const Point z = seeds_[from].position;
    const double r = seeds_[from].radius;
    std::vector<BallTree::Sphere>& near = scratch.near;
    gather_spheres(z, 2 * r, near, scratch);
    for (const Seed& q : out.placed) {
      if ((q.position - z).norm() < 2 * r + q.radius) near.push_back({q.position, q.radius, 0});
    }
    // Most spokes end at the first sphere that covers all of them: the spheres nearest to
    // reaching z first, the big ones among equals.
    std::vector<SpokeSphere>& around = scratch.around;
    nearest_first(z, near, around, scratch);
    for (int misses = 0; misses < options_.misses;) {
      ++out.spokes;
      const Point direction = random_direction(random);
      const std::optional<double> t = uncovered_point(z, direction, r, 2 * r, random.unit(), around, scratch);
      std::optional<Seed> seed;
      if (t) seed = admit(z + *t * direction, out.placed);
      if (!seed) {
        ++misses;
        continue;
      }
      misses = 0;
      out.placed.push_back(*seed);
      around.emplace_back(z, seed->position, seed->radius);
    }
  }

  // Every ball that reaches within `reach` of z: seeds' balls and protecting balls.
  void gather_spheres(const Point& z, double reach, std::vector<BallTree::Sphere>& out, Scratch& scratch) const {
    out.clear();
    for (const BallTree* tree : {&interior_tree_, &surface_tree_}) {
      tree->search(
          z,
          [&](double d2, double max_radius, std::uint32_t) { return d2 < (reach + max_radius) * (reach + max_radius); },
          [&](const BallTree::Sphere& s) {
            if ((s.centre - z).squaredNorm() < (reach + s.radius) * (reach + s.radius)) out.push_back(s);
          });
    }
    for (StratumType type : {StratumType::Corner, StratumType::Crease, StratumType::Patch}) {
      std::vector<std::uint32_t>& balls = scratch.balls;
      balls.clear();
      protecting_.reaching_scaled(type, z, 1 + kBallClearance, reach, balls);
      for (std::uint32_t b : balls) {
        out.push_back({protecting_[b].site.position, (1 + kBallClearance) * protecting_[b].radius, b});
      }
    }
  }

  // The spheres as spokes from z see them (`out`), by their distance from reaching z, equals in
  // the order given.
  static void nearest_first(const Point& z, const std::vector<BallTree::Sphere>& spheres,
                            std::vector<SpokeSphere>& out, Scratch& scratch) {
    std::vector<std::pair<double, std::uint32_t>>& keyed = scratch.keyed;
    keyed.clear();
    for (std::uint32_t k = 0; k < spheres.size(); ++k) {
      keyed.emplace_back((spheres[k].centre - z).norm() - spheres[k].radius, k);
    }
    std::sort(keyed.begin(), keyed.end());
    out.clear();
    for (const auto& [gap, k] : keyed) out.emplace_back(z, spheres[k].centre, spheres[k].radius);
  }

  // A point of the spoke z + t d, t in [t_lo, t_hi], that none of the spheres covers and the box
  // holds, chosen uniformly (u in [0, 1)) over that part's length; nothing when no part is left.
  std::optional<double> uncovered_point(const Point& z, const Point& d, double t_lo, double t_hi, double u,
                                        const std::vector<SpokeSphere>& spheres, Scratch& scratch) const {
    for (int k = 0; k < 3; ++k) {  // the box as a slab per axis
      if (d[k] == 0) continue;
      const double a = (box_.lo[k] - z[k]) / d[k], b = (box_.hi[k] - z[k]) / d[k];
      t_lo = std::max(t_lo, std::min(a, b));
      t_hi = std::min(t_hi, std::max(a, b));
    }
    if (!(t_lo < t_hi)) return std::nullopt;
    std::vector<std::pair<double, double>>& covered = scratch.covered;
    covered.clear();
    for (const SpokeSphere& s : spheres) {
      const auto [a, b] = chord(d, s);
      if (!(a < b && b > t_lo && a < t_hi)) continue;
      if (a <= t_lo && b >= t_hi) return std::nullopt;  // one sphere covers it all: most spokes end here
      covered.emplace_back(std::max(a, t_lo), std::min(b, t_hi));
    }
    std::sort(covered.begin(), covered.end());
    // The free intervals between the merged covered ones, then the point at fraction u of their length.
    std::vector<std::pair<double, double>>& gaps = scratch.gaps;
    gaps.clear();
    double reached = t_lo;
    for (const auto& [a, b] : covered) {
      if (a > reached) gaps.emplace_back(reached, a);
      reached = std::max(reached, b);
    }
    if (reached < t_hi) gaps.emplace_back(reached, t_hi);
    double length = 0;
    for (const auto& [a, b] : gaps) length += b - a;
    if (!(length > 1e-12 * t_hi)) return std::nullopt;
    double target = u * length;
    for (const auto& [a, b] : gaps) {
      if (target < b - a) return a + target;
      target -= b - a;
    }
    return gaps.back().second;
  }

  void add(const Seed& seed) {
    interior_tree_.insert(seed.position, seed.radius, static_cast<std::uint32_t>(seeds_.size()));
    seeds_.push_back(seed);
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
  BallTree surface_tree_, interior_tree_;
  std::vector<Seed> seeds_;
  std::uint32_t given_ = 0;  // seeds_[0, given_) were given (add_given), not sampled
  std::vector<std::uint32_t> passed_over_;  // next_batch's
  tbb::enumerable_thread_specific<Scratch> scratch_;
};

}  // namespace

std::vector<Seed> sample_interior(const std::vector<Seed>& surface_seeds, const std::vector<Seed>& cap_seeds,
                                  const BallIndex& protecting_balls, const SizingField& sizing,
                                  const geometry::Box& domain, const InteriorOptions& options,
                                  const ProgressCallback& progress, InteriorStats& stats) {
  InteriorSampler sampler(surface_seeds, protecting_balls, sizing, domain, options, progress, stats);
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
