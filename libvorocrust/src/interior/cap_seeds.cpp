// Seeds on the protecting spheres (paper 2.5, section 4).
#include "interior/cap_seeds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>

#include "geometry/ball_tree.hpp"
#include "refinement/ball_index.hpp"
#include "refinement/point_cloud.hpp"
#include "seeds/locate_regions.hpp"

namespace vorocrust {

namespace {

constexpr StratumType kTypes[] = {StratumType::Corner, StratumType::Crease, StratumType::Patch};
// Two seeds placed on spheres stay this fraction of the ball's radius apart. Wider would suit
// poles (below) but not repair seeds: at 0.35 or 0.5 the skew repair found no room for seeds it
// needed (cgal_bones: 17 highly skew faces instead of 9; igl_fertility: a highly skew face and a
// cell of aspect ratio 18.5).
constexpr double kSpacing = 0.1;
// A seed placed on one sphere stays this far outside every other ball, in radii, unless it lies
// on that ball's sphere too: just outside a sphere, it would move the Voronoi vertex at the
// ball's centre that the seeds on the sphere share off it, leaving a small skew face there.
constexpr double kClearance = 1.05;
constexpr double kUnbounded = std::numeric_limits<double>::infinity();
constexpr std::uint32_t kNoBall = static_cast<std::uint32_t>(-1);

// How near the balls and the seeds placed a new seed may go.
struct Room {
  double clearance;  // outside every other ball, in its radius
  // Apart from a seed placed by kSpacing of the smaller radius of the two, not of the placed
  // seed's alone.
  bool own_scale;
};
constexpr Room kRoom{kClearance, false};
// Where kRoom leaves none, about a ball far larger than the seeds' own (cgal_bones, where small
// balls of one bone crowd a large one of the next, whose clearance and whose pole's spacing
// cover the whole gap), a repair seed may go just outside the spheres, spaced at its own scale.
constexpr Room kTightRoom{1.005, true};
// A skew face whose centroid lies this near a ball's centre, in radii, may take a seed on its
// sphere this much nearer the seeds placed than kSpacing.
constexpr double kNearCentre = 0.5;
constexpr double kCloseSpacing = 0.01;
constexpr double kPoleOffSeed = 1e-3;  // a pole nearer a seed than this, in radii, would be its twin
// A split of a cell too long stays this far outside every ball, in radii: at 1.05, as seeds on
// spheres do, it cuts small faces about the ball's centre, which the skew repair then crowds with
// seeds on the sphere (igl_fertility: cells of aspect ratio 19 between seeds 0.03 radii apart);
// at 1.3, as interior seeds do, it lies too deep to halve a spindle (igl_bunny --smooth --seed 1
// keeps a cell of 5.18).
constexpr Room kSplitRoom{1.15, false};
// A split stays this far from every seed, in units of the distance from the centroid to the
// cell's seed: nearer, the two cut a small face between them, which may stay highly skew
// (openmeeg_HeadNNa1: splits 0.13 of that apart, where its sheets cross, left two faces of
// skewness 14.4). On igl_bunny --smooth the splits it needs lie 0.75 apart or more.
constexpr double kSplitApart = 0.5;
// A pole's cell is a cone from its ball's centre, as wide as the seeds of its material around the
// pole leave it: with one of them nearer than this, in radii, it is a spindle (igl_bunny
// --smooth: aspect ratios 5 to 6, its worst cells). Such a pole is not placed; the seeds about it
// already lie near the middle of the cap, and the skew repair adds a seed on the sphere where a
// face through the centre is then highly skew.
constexpr double kPoleClearance = 0.4;
// Poles stay this fraction of their radii apart: 0.1 apart, two poles of neighbouring balls make
// two thin cells (igl_bunny --smooth: aspect ratio 6.08).
constexpr double kPoleSpacing = 0.35;
// A material's seeds must agree on a direction this well (the length of their mean unit
// vector) for a pole: seeds spread all round the sphere (a sheet with one material on both
// sides) have no middle.
constexpr double kMinimumMean = 0.02;

// Directions spread evenly over the unit sphere (a Fibonacci lattice), where a repair seed may go
// on a sphere whose pole is missing.
const std::vector<Point> kSpread = [] {
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
bool on_sphere_of(const Point& p, const Point& centre, double radius) {
  return std::abs((p - centre).norm() - radius) <= 1e-9 * radius;
}

// The balls on whose spheres p lies, to rounding.
void spheres_through(const BallIndex& balls, const Point& p, double scale, std::vector<std::uint32_t>& out) {
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
        [&](const BallTree::Sphere& s) {
          // Rounded as the pruning above rounds: an unbounded own radius is BallTree::contains.
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
  BallTree placed_;
  std::uint32_t count_ = 0;
  std::vector<std::uint32_t> near_;
};

}  // namespace

std::vector<Seed> pole_seeds(const std::vector<Seed>& surface_seeds, const BallIndex& balls,
                             const RegionLocator& regions) {
  struct Cap {
    std::int32_t region;
    Point sum;
    int count;
  };
  std::vector<std::vector<Cap>> caps(balls.size());
  std::vector<std::uint32_t> on;
  for (const Seed& s : surface_seeds) {
    if (s.region == kOutsideRegion) continue;
    spheres_through(balls, s.position, s.radius, on);
    for (std::uint32_t b : on) {
      std::vector<Cap>& here = caps[b];
      auto it = std::find_if(here.begin(), here.end(), [&](const Cap& c) { return c.region == s.region; });
      if (it == here.end()) it = here.insert(here.end(), Cap{s.region, Point::Zero(), 0});
      it->sum += (s.position - balls[b].site.position) / balls[b].radius;
      ++it->count;
    }
  }
  // A cap whose seeds lie about one of them (a lone seed, or others symmetric about it) has its
  // pole on that seed, to rounding: the two would be twins, one cell made two by a plane through
  // nearly coincident vertices that no welding tolerance resolves (cgal_bones: a pole 6e-17 from
  // a seed).
  const SeedCloud cloud{&surface_seeds};
  const StaticKdTree<SeedCloud> tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  std::vector<std::uint32_t> near;
  // Whether a seed of the cap's material lies within kPoleClearance of the pole at direction u,
  // or any seed within kPoleOffSeed.
  const auto crowded = [&](std::uint32_t b, const Point& u, std::int32_t region) {
    const Point p = balls[b].site.position + balls[b].radius * u;
    const double clearance = kPoleClearance * balls[b].radius, twin = kPoleOffSeed * balls[b].radius;
    points_within(tree, p, clearance * clearance, near);
    return std::any_of(near.begin(), near.end(), [&](std::uint32_t k) {
      return surface_seeds[k].region == region || (surface_seeds[k].position - p).squaredNorm() < twin * twin;
    });
  };
  SphereSeeds place(balls, regions);
  std::vector<Seed> poles;
  for (std::uint32_t b = 0; b < balls.size(); ++b) {
    for (const Cap& cap : caps[b]) {
      const double length = cap.sum.norm();
      if (!(length > kMinimumMean * cap.count) || crowded(b, cap.sum / length, cap.region)) continue;
      if (const std::optional<Seed> pole = place.place(b, cap.sum / length, cap.region, kPoleSpacing / kSpacing)) {
        poles.push_back(*pole);
      }
    }
  }
  return poles;
}

std::vector<Seed> skew_repair_seeds(const std::vector<cells::CutFace>& skew, const std::vector<Seed>& seeds,
                                    const BallIndex& balls, const RegionLocator& regions,
                                    const std::vector<Seed>& placed) {
  SphereSeeds place(balls, regions, placed);
  std::vector<Seed> added;
  std::vector<std::uint32_t> a, b;
  // The directions from a sphere's centre of the seeds of `region` on it, through a tree of the
  // seeds made when first needed.
  const SeedCloud cloud{&seeds};
  std::unique_ptr<StaticKdTree<SeedCloud>> seed_tree;
  std::vector<std::uint32_t> near;
  const auto on_sphere = [&](const Point& centre, double r, std::int32_t region) {
    if (!seed_tree) seed_tree = std::make_unique<StaticKdTree<SeedCloud>>(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
    points_within(*seed_tree, centre, r * r * (1 + 1e-6), near);
    std::vector<Point> out;
    for (std::uint32_t i : near) {
      if (seeds[i].region == region && on_sphere_of(seeds[i].position, centre, r)) out.push_back((seeds[i].position - centre) / r);
    }
    return out;
  };
  // One face's repair with the room given; whether it placed a seed.
  const auto repair = [&](const cells::CutFace& face, const Room& room) {
    const Seed &s = seeds[face.owner_seed], &t = seeds[static_cast<std::size_t>(face.neighbour_seed)];
    const std::int32_t region = s.region;
    const FaceGeometry& g = face.geometry;
    // A seed at `target`, pushed out of the balls near it, if it stays nearer the target than
    // `from` (a seed of the face) is: it takes the part of the cells about the target.
    const auto place_near = [&](const Point& target, const Point& from) {
      const std::optional<Seed> seed =
          place.place_split(target, from, region, g.normal, room, [](const Point&, double) { return true; });
      if (seed) added.push_back(*seed);
      return seed.has_value();
    };
    // The cell whose centroid lies farther from its seed split at its centroid: that draws the
    // centroid back toward the seed, and the link between the two centroids back through the face.
    const auto split_farther = [&] {
      const bool owner_farther = (face.owner_centroid - s.position).norm() >= (face.neighbour_centroid - t.position).norm();
      return owner_farther ? place_near(face.owner_centroid, s.position) : place_near(face.neighbour_centroid, t.position);
    };
    // Two seeds on spheres (poles, repairs) have cells squeezed between the balls; a seed on yet
    // another sphere makes one more such cell beside them (where openmeeg_HeadNNa1's south half
    // crosses its skull, rounds of them never ended), so these are split first.
    if (s.kind == SeedKind::Cap && t.kind == SeedKind::Cap && split_farther()) return true;
    spheres_through(balls, s.position, s.radius, a);
    spheres_through(balls, t.position, t.radius, b);
    // A narrow wedge through the centre of a sphere both seeds lie on, between seeds there that
    // are nearly cocircular: near the centre every cell of a seed on the sphere is a cone over
    // its part of the sphere. A seed on the sphere toward the face takes the cones' corner there
    // (igl_bunny's big corner balls, with their seeds spread all round). Where that point lies in
    // other balls, as about a sphere whose seeds spread round it in arcs either side of a smaller
    // ball (and which then has no pole), a seed at the free point of the sphere farthest from
    // them replaces the wedge's neighbours by itself.
    for (std::uint32_t q : a) {
      const Point& centre = balls[q].site.position;
      const double r = balls[q].radius;
      if (!std::binary_search(b.begin(), b.end(), q) || !((g.centroid - centre).norm() < kNearCentre * r)) continue;
      const Point towards = g.centroid - centre;
      std::optional<Seed> seed;
      if (towards.norm() > 0) seed = place.place(q, towards.normalized(), region, kCloseSpacing, room);
      if (!seed) seed = place.place_far_from(q, on_sphere(centre, r, region), region, room);
      if (seed) {
        added.push_back(*seed);
        return true;
      }
    }
    // The spheres either seed lies on, those of both first (their centres lie on the face's
    // plane), nearest to the face first; the first that takes a seed toward the face.
    std::vector<std::pair<double, std::uint32_t>> candidates;
    for (const auto* list : {&a, &b}) {
      for (std::uint32_t q : *list) {
        const bool both = std::binary_search(a.begin(), a.end(), q) && std::binary_search(b.begin(), b.end(), q);
        if (!both && list == &b && std::binary_search(a.begin(), a.end(), q)) continue;  // listed once
        candidates.emplace_back((both ? 0 : 1e300) + (balls[q].site.position - g.centroid).norm(), q);
      }
    }
    std::sort(candidates.begin(), candidates.end());
    for (const auto& [order, q] : candidates) {
      const Point towards = g.centroid - balls[q].site.position;
      if (!(towards.norm() > 0)) continue;
      // A face near the centre is a sliver about it (a seed just off the sphere moved the shared
      // vertex there): it needs the seed toward it, however close the seeds already placed.
      const double spacing = towards.norm() < kNearCentre * balls[q].radius ? kCloseSpacing : 1;
      if (const std::optional<Seed> seed = place.place(q, towards.normalized(), region, spacing, room)) {
        added.push_back(*seed);
        return true;
      }
    }
    // No sphere takes one (a face between two seeds on no common sphere, often one a repair
    // seed): a seed at the face's centroid takes the small face's corner of both cells.
    if (place_near(g.centroid, s.position)) return true;
    // No seed may go near the face either (it lies inside a ball).
    return split_farther();
  };
  for (const cells::CutFace& face : skew) {
    if (!face.between_cells) continue;
    if (seeds[face.owner_seed].region != seeds[static_cast<std::size_t>(face.neighbour_seed)].region) continue;
    if (!repair(face, kRoom)) repair(face, kTightRoom);
  }
  return added;
}

std::vector<Seed> aspect_split_seeds(const std::vector<cells::LongCell>& long_cells, const std::vector<Seed>& seeds,
                                     const BallIndex& balls, const RegionLocator& regions,
                                     const std::vector<Seed>& placed) {
  SphereSeeds place(balls, regions, placed);
  const SeedCloud cloud{&seeds};
  const StaticKdTree<SeedCloud> tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  std::vector<std::uint32_t> near;
  BallTree splits;  // those placed here, each with kSplitApart of its reach
  const auto apart = [&](const Point& p, double reach) {
    const double gap = kSplitApart * reach;
    points_within(tree, p, gap * gap, near);
    return near.empty() && !splits.contains(p);
  };
  std::vector<Seed> added;
  for (const cells::LongCell& cell : long_cells) {
    const Seed& own = seeds[cell.seed];
    if (const std::optional<Seed> seed = place.place_split(cell.centroid, own.position, own.region,
                                                           cell.centroid - own.position, kSplitRoom, apart)) {
      splits.insert(seed->position, kSplitApart * seed->radius, static_cast<std::uint32_t>(added.size()));
      added.push_back(*seed);
    }
  }
  return added;
}

}  // namespace vorocrust
