#include "clipping/poisson_disk_seeds.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/c_format.hpp"
#include "core/split_mix.hpp"
#include "geometry/box_tree.hpp"
#include "geometry/nearest_face.hpp"
#include "seeds/locate_regions.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust::clipping {
namespace {

constexpr int kLevels = 6;           // cubes split down to a 64th of the grid's side
constexpr double kDartsPerCube = 2;  // darts at each level, per live cube

struct Cube {
  Point lo;
  bool near_surface = false;  // the surface may cross it
};

geometry::Box box_of(const SurfaceMesh& domain) {
  geometry::Box box;
  for (const Point& p : domain.vertices) box.include(p);
  return box;
}

class Sampler {
 public:
  Sampler(const SurfaceMesh& domain, std::int32_t material, double radius, std::uint64_t seed,
          const std::vector<Seed>& placed)
      : material_(material),
        r_(radius),
        side_(radius / std::sqrt(3.0)),
        locate_(domain),
        faces_(geometry::boundary_tree(domain, material)),
        random_(seed) {
    const geometry::Box box = box_of(domain);
    lo_ = box.lo;
    for (int k = 0; k < 3; ++k)
      dims_[k] = std::max<std::int64_t>(1, std::llround(std::ceil((box.hi[k] - box.lo[k]) / side_)));
    const double cells = static_cast<double>(dims_[0]) * static_cast<double>(dims_[1]) * static_cast<double>(dims_[2]);
    if (cells > 2e9) {
      throw Error(Error::Kind::Usage,
                  c_format("a Poisson-disk radius of %.3g needs a grid of %.3g cubes over the input: raise `max_size`",
                           radius, cells),
                  {.option = "max_size"});
    }
    grid_.assign(static_cast<std::size_t>(cells), -1);
    // Placed interior seeds (a lattice) within r of a placed seed of another kind (on an edge)
    // give way to it.
    for (const Seed& s : placed) {
      const bool crowded = s.kind == SeedKind::Interior && any_near(s.position, [&](const Seed& other) {
                             return other.kind != SeedKind::Interior && (other.position - s.position).norm() < r_;
                           });
      if (!crowded) add(s);
    }
  }

  std::vector<Seed> run() {
    std::vector<Cube> live = grid_cubes();
    double side = side_;
    for (int level = 0; level <= kLevels && !live.empty(); ++level) {
      throw_darts(live, side);
      if (level == kLevels) break;
      std::vector<Cube> next;
      for (const Cube& c : live) {
        if (!covered(c, side)) split(c, side, next);
      }
      live = std::move(next);
      side /= 2;
    }
    return std::move(seeds_);
  }

 private:
  std::array<std::int64_t, 3> cell_of(const Point& p) const {
    std::array<std::int64_t, 3> c{};
    for (int k = 0; k < 3; ++k) {
      c[k] = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((p[k] - lo_[k]) / side_)), 0, dims_[k] - 1);
    }
    return c;
  }
  std::size_t flat(const std::array<std::int64_t, 3>& c) const {
    return static_cast<std::size_t>((c[2] * dims_[1] + c[1]) * dims_[0] + c[0]);
  }

  // Calls visit(seed) for the seeds of the grid cells within two of p's: every seed
  // within r of p (r spans less than two grid cells).
  template <class Visit>
  bool any_near(const Point& p, Visit&& visit) const {
    const auto c = cell_of(p);
    for (std::int64_t z = std::max<std::int64_t>(0, c[2] - 2); z <= std::min(dims_[2] - 1, c[2] + 2); ++z) {
      for (std::int64_t y = std::max<std::int64_t>(0, c[1] - 2); y <= std::min(dims_[1] - 1, c[1] + 2); ++y) {
        for (std::int64_t x = std::max<std::int64_t>(0, c[0] - 2); x <= std::min(dims_[0] - 1, c[0] + 2); ++x) {
          for (std::int32_t s = grid_[flat({x, y, z})]; s >= 0; s = next_[static_cast<std::size_t>(s)]) {
            if (visit(seeds_[static_cast<std::size_t>(s)])) return true;
          }
        }
      }
    }
    return false;
  }

  bool within_r(const Point& p) const {
    return any_near(p, [&](const Seed& s) { return (s.position - p).squaredNorm() < r_ * r_; });
  }

  // A seed's ball holds the whole cube: the ball is convex, so holding its corners is enough.
  bool covered(const Cube& c, double side) const {
    const Point centre = c.lo + Point::Constant(side / 2);
    return any_near(centre, [&](const Seed& s) {
      for (int k = 0; k < 8; ++k) {
        const Point corner = c.lo + side * Point(k & 1, (k >> 1) & 1, (k >> 2) & 1);
        if ((corner - s.position).squaredNorm() >= r_ * r_) return false;
      }
      return true;
    });
  }

  bool inside(const Point& p) const { return locate_.region_of(p) == material_; }

  // A cube holds one sampled seed at most, but placed seeds (on reflex edges, r / sqrt(2) apart)
  // may share one: each cube heads a list.
  void add(const Seed& s) {
    std::int32_t& head = grid_[flat(cell_of(s.position))];
    next_.push_back(head);
    head = static_cast<std::int32_t>(seeds_.size());
    seeds_.push_back(s);
  }

  bool near_surface(const Point& lo, double side) const {
    geometry::Box box;
    box.include(lo);
    box.include(lo + Point::Constant(side));
    bool near = false;
    faces_.for_each_overlap(box, [&](std::uint32_t) { near = true; });
    return near;
  }

  // The grid's cubes that may take a seed: those the surface may cross (whose boxes a triangle's
  // box meets), and those inside the material. The others lie on one side of the surface, as do
  // their neighbours away from it: one ray decides for each connected set of them.
  std::vector<Cube> grid_cubes() {
    enum : std::int8_t { kUnknown, kNear, kInside, kOutside };
    std::vector<std::int8_t> state(grid_.size(), kUnknown);
    faces_.for_each_where([](const geometry::Box&) { return true; },
                          [&](std::uint32_t t) {
                            const geometry::Box& b = faces_.box(t);
                            const auto lo = cell_of(b.lo), hi = cell_of(b.hi);
                            for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
                              for (std::int64_t y = lo[1]; y <= hi[1]; ++y) {
                                for (std::int64_t x = lo[0]; x <= hi[0]; ++x) state[flat({x, y, z})] = kNear;
                              }
                            }
                          });
    std::vector<std::array<std::int64_t, 3>> stack;
    for (std::int64_t z = 0; z < dims_[2]; ++z) {
      for (std::int64_t y = 0; y < dims_[1]; ++y) {
        for (std::int64_t x = 0; x < dims_[0]; ++x) {
          if (state[flat({x, y, z})] != kUnknown) continue;
          const std::int8_t side = inside(corner_of({x, y, z}) + Point::Constant(side_ / 2)) ? kInside : kOutside;
          state[flat({x, y, z})] = side;
          stack.push_back({x, y, z});
          while (!stack.empty()) {
            const auto c = stack.back();
            stack.pop_back();
            for (int k = 0; k < 6; ++k) {
              auto d = c;
              d[k / 2] += k % 2 ? 1 : -1;
              if (d[k / 2] < 0 || d[k / 2] >= dims_[k / 2] || state[flat(d)] != kUnknown) continue;
              state[flat(d)] = side;
              stack.push_back(d);
            }
          }
        }
      }
    }
    std::vector<Cube> live;
    for (std::int64_t z = 0; z < dims_[2]; ++z) {
      for (std::int64_t y = 0; y < dims_[1]; ++y) {
        for (std::int64_t x = 0; x < dims_[0]; ++x) {
          const std::int8_t s = state[flat({x, y, z})];
          if (s == kNear || s == kInside) live.push_back({corner_of({x, y, z}), s == kNear});
        }
      }
    }
    return live;
  }

  Point corner_of(const std::array<std::int64_t, 3>& c) const {
    return lo_ + side_ * Point(static_cast<double>(c[0]), static_cast<double>(c[1]), static_cast<double>(c[2]));
  }

  // Whether a point of the cube at a quarter of its side (27 of them) is inside the material and
  // not yet within r of a seed.
  bool open_inside(const Cube& c, double side) const {
    for (int k = 0; k < 27; ++k) {
      const Point p = c.lo + side / 2 * Point(k % 3, (k / 3) % 3, k / 9);
      if (!within_r(p) && inside(p)) return true;
    }
    return false;
  }

  // The parts of an uncovered cube that may still take a seed. The parts of a cube away from the
  // surface are inside the material, as it is. A cube the surface may cross is tested at its 27
  // half-side points, its parts' corners: a part the surface may cross is kept where one of its
  // corners is inside the material and not yet within r of a seed; a part away from it, where
  // its centre is inside.
  void split(const Cube& c, double side, std::vector<Cube>& next) {
    const double half = side / 2;
    const auto point = [&](int x, int y, int z) -> Point { return c.lo + half * Point(x, y, z); };
    std::array<bool, 27> open{};
    if (c.near_surface) {
      for (int k = 0; k < 27; ++k) {
        const Point p = point(k % 3, (k / 3) % 3, k / 9);
        open[static_cast<std::size_t>(k)] = !within_r(p) && inside(p);
      }
    }
    for (int j = 0; j < 8; ++j) {
      const int jx = j & 1, jy = (j >> 1) & 1, jz = (j >> 2) & 1;
      Cube part{point(jx, jy, jz), false};
      if (covered(part, half)) continue;
      if (!c.near_surface) {
        next.push_back(part);
        continue;
      }
      part.near_surface = near_surface(part.lo, half);
      bool keep = false;
      if (part.near_surface) {
        for (int k = 0; k < 8 && !keep; ++k) {
          keep = open[static_cast<std::size_t>((jx + (k & 1)) + 3 * (jy + ((k >> 1) & 1)) + 9 * (jz + ((k >> 2) & 1)))];
        }
        keep = keep || open_inside(part, half);
      } else {
        keep = inside(part.lo + Point::Constant(half / 2));
      }
      if (keep) next.push_back(part);
    }
  }

  void throw_darts(std::vector<Cube>& live, double side) {
    const auto darts = static_cast<std::size_t>(kDartsPerCube * static_cast<double>(live.size()));
    for (std::size_t d = 0; d < darts; ++d) {
      const auto i = static_cast<std::size_t>(random_.unit() * static_cast<double>(live.size()));
      const Cube& c = live[i];
      const Point p = c.lo + side * Point(random_.unit(), random_.unit(), random_.unit());
      if (within_r(p) || (c.near_surface && !inside(p))) continue;
      add({p, material_, r_, SeedKind::Interior});
    }
  }

  std::int32_t material_;
  double r_, side_;
  Point lo_;
  std::array<std::int64_t, 3> dims_{};
  std::vector<std::int32_t> grid_;  // each cube's last seed, -1 for none
  std::vector<std::int32_t> next_;  // each seed's predecessor in its cube
  std::vector<Seed> seeds_;
  RegionLocator locate_;
  geometry::BoxTree faces_;  // the material's boundary
  SplitMix64 random_;
};

}  // namespace

std::vector<Seed> poisson_disk_seeds(const SurfaceMesh& domain, std::int32_t material, double radius,
                                     std::uint64_t seed, const std::vector<Seed>& placed) {
  return Sampler(domain, material, radius, seed, placed).run();
}

std::vector<Seed> outside_seeds(const SurfaceMesh& domain, double margin, double spacing) {
  const geometry::Box box = box_of(domain);
  const Point lo = box.lo - Point::Constant(margin), hi = box.hi + Point::Constant(margin);
  std::array<int, 3> n{};
  for (int k = 0; k < 3; ++k) n[k] = std::max(1, static_cast<int>(std::ceil((hi[k] - lo[k]) / spacing)));
  std::vector<Seed> seeds;
  for (int z = 0; z <= n[2]; ++z) {
    for (int y = 0; y <= n[1]; ++y) {
      for (int x = 0; x <= n[0]; ++x) {
        if (x != 0 && x != n[0] && y != 0 && y != n[1] && z != 0 && z != n[2]) continue;
        const Point t(double(x) / n[0], double(y) / n[1], double(z) / n[2]);
        seeds.push_back({lo + (hi - lo).cwiseProduct(t), kOutsideRegion, spacing, SeedKind::Outside});
      }
    }
  }
  return seeds;
}

}  // namespace vorocrust::clipping
