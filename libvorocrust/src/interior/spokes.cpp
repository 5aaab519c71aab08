// Spoke darts (paper A.5): from each seed, spokes on which new seeds land where no ball covers them.
#include "interior/interior_sampler.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>
#include <optional>
#include <span>

#include "refinement/ball_index.hpp"

namespace vorocrust::interior {

// A direction uniform on the unit sphere (Archimedes: the height is uniform in [-1, 1]), from
// two uniform numbers; three normal deviates cost twice as much, a tenth of the sampler.
Point InteriorSampler::random_direction(SplitMix64& random) {
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
void InteriorSampler::shoot_spokes(std::deque<std::uint32_t> queue) {
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

// The sampled seeds whose spokes may find room the shrinking of `shrunk` (seeds and their radii
// before) freed: their own ball shrank, or their shell of spokes, out to 2 r, meets a ball as
// it was. The paper shoots from all seeds again; the others' spokes meet the balls they met.
// Each seed asks a tree of the shrunk balls as they were: searched from the shrunk balls, the
// tree of all seeds bounds its nodes by the outside seeds' large radii, and prunes little.
std::deque<std::uint32_t> InteriorSampler::seeds_near(const std::vector<std::pair<std::uint32_t, double>>& shrunk) const {
  geometry::BallTree before;
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
          [&](const geometry::BallTree::Sphere& s) {
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

// The next batch: groups of seeds from the front of the queue, such that the spokes of a
// group and the balls they place cannot meet another group's (a spoke from z reaches 2 r_z,
// and the ball of a seed it places at most 1.5 r_z, by the Lipschitz bound through z), so
// that the groups place what they would one after the other. A seed joins the one group it
// comes near, or starts one; seeds near two groups, or that find theirs full or no group left,
// keep their places at the front. Groups of neighbours keep each thread's memory warm.
void InteriorSampler::next_batch(std::deque<std::uint32_t>& queue, std::vector<SpokeGroup>& groups) {
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
void InteriorSampler::spokes_from(std::uint32_t from, Scratch& scratch, SpokeWork& out) const {
  SplitMix64 random = SplitMix64::stream(options_.seed ^ kSpokeStreams, (std::uint64_t{stats_.rounds} << 32) | from);
  const Point z = seeds_[from].position;
  const double r = seeds_[from].radius;
  std::vector<geometry::BallTree::Sphere>& near = scratch.near;
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
void InteriorSampler::gather_spheres(const Point& z, double reach, std::vector<geometry::BallTree::Sphere>& out, Scratch& scratch) const {
  out.clear();
  for (const geometry::BallTree* tree : {&interior_tree_, &surface_tree_}) {
    tree->search(
        z,
        [&](double d2, double max_radius, std::uint32_t) { return d2 < (reach + max_radius) * (reach + max_radius); },
        [&](const geometry::BallTree::Sphere& s) {
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
void InteriorSampler::nearest_first(const Point& z, const std::vector<geometry::BallTree::Sphere>& spheres,
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
std::optional<double> InteriorSampler::uncovered_point(const Point& z, const Point& d, double t_lo, double t_hi, double u,
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

}  // namespace vorocrust::interior
