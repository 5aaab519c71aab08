// Internal: seeds placed on the protecting spheres and near them, and the room they keep.
//
// SphereSeeds decides where a seed on a sphere may go (outside the other balls by a clearance,
// clear of the seeds placed this way, in the material it is placed for) and remembers those
// placed. The poles (interior/cap_seeds.hpp) and the repairs of the cells (cells/repair_seeds.hpp)
// both place their seeds through it, with the spacing rules below.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "geometry/ball_tree.hpp"
#include "refinement/ball_index.hpp"
#include "geometry/point_cloud.hpp"
#include "seeds/locate_regions.hpp"
#include "vorocrust/seeds.hpp"

namespace vorocrust::interior {

inline constexpr StratumType kTypes[] = {StratumType::Corner, StratumType::Crease, StratumType::Patch};
// Two seeds placed on spheres stay this fraction of the ball's radius apart. Wider would suit
// poles (below) but not repair seeds: at 0.35 or 0.5 the skew repair found no room for seeds it
// needed (cgal_bones: 17 highly skew faces instead of 9; igl_fertility: a highly skew face and a
// cell of aspect ratio 18.5).
inline constexpr double kSpacing = 0.1;
// A seed placed on one sphere stays this far outside every other ball, in radii, unless it lies
// on that ball's sphere too: just outside a sphere, it would move the Voronoi vertex at the
// ball's centre that the seeds on the sphere share off it, leaving a small skew face there.
inline constexpr double kClearance = 1.05;
inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();
inline constexpr std::uint32_t kNoBall = static_cast<std::uint32_t>(-1);

// How near the balls and the seeds placed a new seed may go.
struct Room {
  double clearance;  // outside every other ball, in its radius
  // Apart from a seed placed by kSpacing of the smaller radius of the two, not of the placed
  // seed's alone.
  bool own_scale;
};
inline constexpr Room kRoom{kClearance, false};
// Where kRoom leaves none, about a ball far larger than the seeds' own (cgal_bones, where small
// balls of one bone crowd a large one of the next, whose clearance and whose pole's spacing
// cover the whole gap), a repair seed may go just outside the spheres, spaced at its own scale.
inline constexpr Room kTightRoom{1.005, true};
// A skew face whose centroid lies this near a ball's centre, in radii, may take a seed on its
// sphere this much nearer the seeds placed than kSpacing.
inline constexpr double kNearCentre = 0.5;
inline constexpr double kCloseSpacing = 0.01;
inline constexpr double kPoleOffSeed = 1e-3;  // a pole nearer a seed than this, in radii, would be its twin
// A split of a cell too long stays this far outside every ball, in radii: at 1.05, as seeds on
// spheres do, it cuts small faces about the ball's centre, which the skew repair then crowds with
// seeds on the sphere (igl_fertility: cells of aspect ratio 19 between seeds 0.03 radii apart);
// at 1.3, as interior seeds do, it lies too deep to halve a spindle (igl_bunny --smooth --seed 1
// keeps a cell of 5.18).
inline constexpr Room kSplitRoom{1.15, false};
// A split stays this far from every seed, in units of the distance from the centroid to the
// cell's seed: nearer, the two cut a small face between them, which may stay highly skew
// (openmeeg_HeadNNa1: splits 0.13 of that apart, where its sheets cross, left two faces of
// skewness 14.4). On igl_bunny --smooth the splits it needs lie 0.75 apart or more.
inline constexpr double kSplitApart = 0.5;
// A pole's cell is a cone from its ball's centre, as wide as the seeds of its material around the
// pole leave it: with one of them nearer than this, in radii, it is a spindle (igl_bunny
// --smooth: aspect ratios 5 to 6, its worst cells). Such a pole is not placed; the seeds about it
// already lie near the middle of the cap, and the skew repair adds a seed on the sphere where a
// face through the centre is then highly skew.
inline constexpr double kPoleClearance = 0.4;
// Poles stay this fraction of their radii apart: 0.1 apart, two poles of neighbouring balls make
// two thin cells (igl_bunny --smooth: aspect ratio 6.08).
inline constexpr double kPoleSpacing = 0.35;
// A material's seeds must agree on a direction this well (the length of their mean unit
// vector) for a pole: seeds spread all round the sphere (a sheet with one material on both
// sides) have no middle.
inline constexpr double kMinimumMean = 0.02;

// Directions spread evenly over the unit sphere (a Fibonacci lattice), where a repair seed may go
// on a sphere whose pole is missing.
inline const std::vector<Point> kSpread = [] {
  constexpr int n = 96;
  const double turn = std::numbers::pi * (3 - std::sqrt(5.0));
  std::vector<Point> out;
  for (int k = 0; k < n; ++k) {
    const double z = 1 - (2 * k + 1) / static_cast<double>(n);
    const double rho = std::sqrt(1 - z * z);
    out.emplace_back(rho * std::cos(turn * k), rho * std::sin(turn * k), z);
  }
  return out;
}();


// Whether p lies on the sphere of `centre` and `radius`, to rounding: seeds placed at a ball-triplet
// point or on a sphere sit there up to the last digits.
inline bool on_sphere_of(const Point& p, const Point& centre, double radius) {
  return std::abs((p - centre).norm() - radius) <= 1e-9 * radius;
}

// The balls on whose spheres p lies, to rounding.
inline void spheres_through(const BallIndex& balls, const Point& p, double scale, std::vector<std::uint32_t>& out) {
  out.clear();
  std::vector<std::uint32_t> near;
  for (StratumType type : kTypes) {
    near.clear();
    balls.reaching(type, p, 1e-6 * scale, near);
    for (std::uint32_t b : near) {
      if (on_sphere_of(p, balls[b].site.position, balls[b].radius)) out.push_back(b);
    }
  }
  std::sort(out.begin(), out.end());
}

// Decides where a seed on a sphere may go, and remembers those placed.
class SphereSeeds {
 public:
  // `placed`: seeds on spheres and splits placed before, which those placed now keep clear of.
  SphereSeeds(const BallIndex& balls, const RegionLocator& regions, const std::vector<Seed>& placed = {})
      : balls_(balls), regions_(regions) {
    for (const Seed& s : placed) remember(s);
  }

  void remember(const Seed& s) { placed_.insert(s.position, kSpacing * s.radius, count_++); }
  // Whether p lies within `spacing` (a fraction of kSpacing) of the radius of a seed placed.
  // With `own_radius`, within `spacing` of that radius if it is the smaller.
  bool near_placed(const Point& p, double spacing = 1, double own_radius = kUnbounded) const {
    const double own = kSpacing * own_radius;
    bool near = false;
    placed_.search(
        p, [&](double d2, double max_radius, std::uint32_t) { return !near && d2 < spacing * spacing * max_radius * max_radius; },
        [&](const geometry::BallTree::Sphere& s) {
          // Rounded as the pruning above rounds: an unbounded own radius is geometry::BallTree::contains.
          const double r = std::min(s.radius, own);
          near = near || (s.centre - p).squaredNorm() < spacing * spacing * r * r;
        });
    return near;
  }

  // The seed of material `region` at direction u (unit) on ball b's sphere, if it may go there;
  // `spacing` scales the distance it keeps from the seeds placed.
  std::optional<Seed> place(std::uint32_t b, const Point& u, std::int32_t region, double spacing = 1,
                            const Room& room = kRoom) {
    const Point& centre = balls_[b].site.position;
    const double r = balls_[b].radius;
    const Point p = centre + r * u;
    if (blocking_ball(p, b, room.clearance)) return std::nullopt;
    if (near_placed(p, spacing, room.own_scale ? r : kUnbounded)) return std::nullopt;
    if (regions_.region_of(p, u) != region) return std::nullopt;
    Seed s{p, region, r, SeedKind::Cap};
    remember(s);
    return s;
  }

  // The seed at the free point of ball b's sphere farthest from `seeds` (directions from its
  // centre), of the spread directions.
  std::optional<Seed> place_far_from(std::uint32_t b, const std::vector<Point>& seeds, std::int32_t region,
                                    const Room& room = kRoom) {
    std::vector<std::pair<double, int>> order;
    for (int k = 0; k < static_cast<int>(kSpread.size()); ++k) {
      double nearest = 4;
      for (const Point& v : seeds) nearest = std::min(nearest, (kSpread[k] - v).squaredNorm());
      order.emplace_back(-nearest, k);
    }
    std::sort(order.begin(), order.end());
    for (const auto& [score, k] : order) {
      if (std::optional<Seed> s = place(b, kSpread[k], region, 1, room)) return s;
    }
    return std::nullopt;
  }

  // A seed of `region` at `target`, pushed out of the balls (pushed_clear), if it stays nearer
  // the target than `from`, the seed of the cell it splits, is: pushed farther, it would take
  // that seed's end of the cell instead. `direction`: the ray that finds its side;
  // `accept(p, reach)` may refuse the point p, `reach` being the distance from `from` to the target.
  template <class Accept>
  std::optional<Seed> place_split(const Point& target, const Point& from, std::int32_t region, const Point& direction,
                                  const Room& room, Accept&& accept) {
    const double reach = (target - from).norm();
    const std::optional<Point> p = pushed_clear(target, room.clearance);
    if (!p || !(reach > 0) || !((*p - target).norm() < reach) || regions_.region_of(*p, direction) != region ||
        near_placed(*p, 1, room.own_scale ? reach : kUnbounded) || !accept(*p, reach)) {
      return std::nullopt;
    }
    Seed seed{*p, region, reach, SeedKind::Repair};
    remember(seed);
    return seed;
  }

  // p moved out of the balls that hold it or lie too near (within `clearance` times their
  // radii), each time radially to the clearance of the one nearest to holding it, a few times at
  // most; nothing when it does not get clear.
  std::optional<Point> pushed_clear(Point p, double clearance = kClearance) {
    for (int step = 0; step < 12; ++step) {
      const std::optional<std::uint32_t> q = blocking_ball(p, kNoBall, clearance);
      if (!q) return p;
      const Point& centre = balls_[*q].site.position;
      const Point away = p - centre;
      if (!(away.norm() > 0)) return std::nullopt;
      p = centre + clearance * (1 + 1e-9) * balls_[*q].radius * away.normalized();
    }
    return std::nullopt;
  }

 private:
  // The ball p is deepest in, in radii, among those it lies inside or within `clearance` times
  // the radius of (other than `own`, and than those on whose sphere it lies).
  std::optional<std::uint32_t> blocking_ball(const Point& p, std::uint32_t own, double clearance = kClearance) {
    std::optional<std::uint32_t> deepest;
    double depth = 0;
    for (StratumType type : kTypes) {
      near_.clear();
      balls_.reaching_scaled(type, p, clearance, 0, near_);
      for (std::uint32_t q : near_) {
        if (q == own || on_sphere_of(p, balls_[q].site.position, balls_[q].radius)) continue;
        const double d = (p - balls_[q].site.position).norm();
        if (!deepest || d / balls_[q].radius < depth) {
          deepest = q;
          depth = d / balls_[q].radius;
        }
      }
    }
    return deepest;
  }

  const BallIndex& balls_;
  const RegionLocator& regions_;
  geometry::BallTree placed_;
  std::uint32_t count_ = 0;
  std::vector<std::uint32_t> near_;
};


}  // namespace vorocrust::interior
