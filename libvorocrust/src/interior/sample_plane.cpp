// Interior seeds of a 2D domain: dart throwing grown from the boundary, or a lattice first
// (paper 2.5 and 2.6).
#include "interior/sample_plane.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>
#include <unordered_map>

#include "core/split_mix.hpp"
#include "geometry/plane_tree.hpp"

namespace vorocrust::interior {

struct PlaneSpacing::Impl {
  std::vector<Point2> centres;
  std::vector<double> radii;
  geometry::PlaneTree tree;
  const SizingField& sizing;
  double lipschitz, largest, widest = 0;
  Impl(const std::vector<PlaneCircle>& circles, const SizingField& s, double l, double cap)
      : centres(centres_of(circles)), tree(centres), sizing(s), lipschitz(l), largest(cap) {
    for (const PlaneCircle& c : circles) {
      radii.push_back(c.radius);
      widest = std::max(widest, c.radius);
    }
  }
  static std::vector<Point2> centres_of(const std::vector<PlaneCircle>& circles) {
    std::vector<Point2> out;
    for (const PlaneCircle& c : circles) out.push_back(c.centre);
    return out;
  }
};

PlaneSpacing::PlaneSpacing(const std::vector<PlaneCircle>& circles, const SizingField& sizing, double lipschitz,
                           double largest)
    : impl_(std::make_shared<Impl>(circles, sizing, lipschitz, largest)) {}

double PlaneSpacing::operator()(const Point2& x) const {
  constexpr std::size_t kNearest = 16;
  std::uint32_t index[kNearest];
  double squared[kNearest];
  double best = std::min(impl_->largest, impl_->sizing(Point(x.x(), x.y(), 0)));
  const std::size_t found = impl_->tree.nearest(x, kNearest, index, squared);
  for (std::size_t k = 0; k < found; ++k) best = std::min(best, impl_->radii[index[k]] + impl_->lipschitz * std::sqrt(squared[k]));
  return best;
}

bool PlaneSpacing::in_circles(const Point2& x, double factor) const {
  thread_local std::vector<std::uint32_t> near;
  impl_->tree.within(x, factor * impl_->widest, near);
  return std::any_of(near.begin(), near.end(), [&](std::uint32_t c) {
    return (x - impl_->centres[c]).norm() < factor * impl_->radii[c];
  });
}

double PlaneSpacing::lipschitz() const { return impl_->lipschitz; }

namespace {

// Seeds by spacing level: a seed of spacing t sits in the grid of cells 2^floor(log2 t) wide,
// so a query looks at a few cells of the few levels a Lipschitz spacing allows nearby.
class DiskGrid {
 public:
  explicit DiskGrid(double lipschitz) : lipschitz_(std::min(lipschitz, 0.9)) {}

  void insert(const Point2& p, double spacing) {
    const int level = level_of(spacing);
    points_.push_back(p);
    levels_[level][key(p, level)].push_back(static_cast<std::uint32_t>(points_.size() - 1));
  }
  // Whether a seed lies nearer p than `spacing`.
  bool conflicts(const Point2& p, double spacing) const {
    const int lo = level_of((1 - lipschitz_) * spacing) - 1, hi = level_of((1 + lipschitz_) * spacing) + 1;
    for (int level = lo; level <= hi; ++level) {
      const auto it = levels_.find(level);
      if (it == levels_.end()) continue;
      const double cell = std::ldexp(1.0, level);
      const auto x0 = static_cast<std::int64_t>(std::floor((p.x() - spacing) / cell));
      const auto x1 = static_cast<std::int64_t>(std::floor((p.x() + spacing) / cell));
      const auto y0 = static_cast<std::int64_t>(std::floor((p.y() - spacing) / cell));
      const auto y1 = static_cast<std::int64_t>(std::floor((p.y() + spacing) / cell));
      for (std::int64_t i = x0; i <= x1; ++i) {
        for (std::int64_t j = y0; j <= y1; ++j) {
          const auto cellit = it->second.find(pack(i, j));
          if (cellit == it->second.end()) continue;
          for (std::uint32_t s : cellit->second) {
            if ((points_[s] - p).squaredNorm() < spacing * spacing) return true;
          }
        }
      }
    }
    return false;
  }

 private:
  static int level_of(double spacing) { return std::ilogb(spacing); }
  static std::uint64_t pack(std::int64_t i, std::int64_t j) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(i)) << 32) | static_cast<std::uint32_t>(j);
  }
  static std::uint64_t key(const Point2& p, int level) {
    const double cell = std::ldexp(1.0, level);
    return pack(static_cast<std::int64_t>(std::floor(p.x() / cell)), static_cast<std::int64_t>(std::floor(p.y() / cell)));
  }
  double lipschitz_;
  std::vector<Point2> points_;
  std::unordered_map<int, std::unordered_map<std::uint64_t, std::vector<std::uint32_t>>> levels_;
};

constexpr int kTries = 12;

}  // namespace

std::vector<Seed> sample_plane(const std::vector<Seed>& boundary, const PlaneSpacing& spacing,
                               const Eigen::AlignedBox2d& frame, InteriorMode mode, double lattice_spacing,
                               std::uint64_t seed) {
  DiskGrid grid(spacing.lipschitz());
  std::vector<Seed> out;
  std::deque<std::pair<Point2, double>> active;
  for (const Seed& s : boundary) {
    const Point2 p(s.position.x(), s.position.y());
    const double t = spacing(p);
    grid.insert(p, t);
    active.emplace_back(p, t);
  }
  const auto accept = [&](const Point2& q, double t) {
    grid.insert(q, t);
    out.push_back({Point(q.x(), q.y(), 0), kOutsideRegion, t, SeedKind::Interior});
    active.emplace_back(q, t);
  };
  const auto allowed = [&](const Point2& q, double t) {
    return frame.contains(q) && !spacing.in_circles(q, kPlaneClearance) && !grid.conflicts(q, t);
  };
  if (mode == InteriorMode::Lattice && lattice_spacing > 0) {
    // Rows of a hexagonal lattice, half a spacing shifted every other row.
    const double h = lattice_spacing, row = h * std::sqrt(3.0) / 2;
    const auto rows = static_cast<std::int64_t>(std::floor(frame.sizes().y() / row));
    const auto columns = static_cast<std::int64_t>(std::floor(frame.sizes().x() / h));
    for (std::int64_t j = 0; j <= rows; ++j) {
      for (std::int64_t i = 0; i <= columns; ++i) {
        const Point2 q = frame.min() + Point2((static_cast<double>(i) + (j % 2 ? 0.5 : 0.0)) * h, static_cast<double>(j) * row);
        if (spacing(q) >= h && allowed(q, h)) accept(q, h);
      }
    }
  }
  SplitMix64 random = SplitMix64::stream(seed, 0x2d);
  while (!active.empty()) {
    const auto [p, t] = active.front();
    active.pop_front();
    for (int k = 0; k < kTries; ++k) {
      const double angle = 2 * std::numbers::pi * random.unit();
      const double reach = t * (1 + random.unit());
      const Point2 q = p + reach * Point2(std::cos(angle), std::sin(angle));
      if (!frame.contains(q)) continue;
      const double tq = spacing(q);
      if (allowed(q, tq)) accept(q, tq);
    }
  }
  return out;
}

}  // namespace vorocrust::interior
