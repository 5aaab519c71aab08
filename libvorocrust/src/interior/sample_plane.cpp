// Interior seeds of a 2D domain: dart throwing grown from the boundary, or a lattice first
// (paper 2.5 and 2.6).
#include "interior/sample_plane.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numbers>
#include <unordered_map>

#include <tbb/parallel_for.h>

#include "core/split_mix.hpp"
#include "geometry/plane_tree.hpp"

namespace vorocrust::interior {

struct PlaneSpacing::Impl {
  std::vector<Point2> centres;
  std::vector<double> radii;
  geometry::PlaneTree tree;
  const SizingField& sizing;
  double lipschitz, largest, widest = 0, smallest = std::numeric_limits<double>::infinity();
  // A coarse grid over the frame: per cell, whether every point in it has the largest spacing
  // (kCapped) and lies clear of the circles (kClear), as the nearest centre to its middle shows.
  static constexpr std::uint8_t kCapped = 1, kClear = 2;
  Eigen::AlignedBox2d frame;
  double cell = 0;
  std::int64_t columns = 0, rows = 0;
  std::vector<std::uint8_t> flags;
  Impl(const std::vector<PlaneCircle>& circles, const SizingField& s, double l, double cap, const Eigen::AlignedBox2d& f)
      : centres(centres_of(circles)), tree(centres), sizing(s), lipschitz(l), largest(cap), frame(f) {
    for (const PlaneCircle& c : circles) {
      radii.push_back(c.radius);
      widest = std::max(widest, c.radius);
      smallest = std::min(smallest, c.radius);
    }
    const double top = std::min(largest, sizing(Point(f.center().x(), f.center().y(), 0)));
    cell = std::max(2 * top, f.sizes().maxCoeff() / 1024);
    columns = static_cast<std::int64_t>(std::ceil(f.sizes().x() / cell));
    rows = static_cast<std::int64_t>(std::ceil(f.sizes().y() / cell));
    flags.assign(static_cast<std::size_t>(columns * rows), 0);
    const double half = cell * std::sqrt(0.5);
    tbb::parallel_for(std::int64_t{0}, rows, [&](std::int64_t j) {
      for (std::int64_t i = 0; i < columns; ++i) {
        const Point2 middle = f.min() + cell * Point2(static_cast<double>(i) + 0.5, static_cast<double>(j) + 0.5);
        std::uint32_t nearest;
        double squared;
        if (tree.nearest(middle, 1, &nearest, &squared) == 0) continue;
        const double reach = std::sqrt(squared) - half;
        std::uint8_t flag = 0;
        if (sizing.uniform() && smallest + lipschitz * reach >= top) flag |= kCapped;
        if (reach >= kPlaneClearance * widest) flag |= kClear;
        flags[static_cast<std::size_t>(j * columns + i)] = flag;
      }
    });
  }
  std::uint8_t flags_at(const Point2& x) const {
    const auto i = static_cast<std::int64_t>(std::floor((x.x() - frame.min().x()) / cell));
    const auto j = static_cast<std::int64_t>(std::floor((x.y() - frame.min().y()) / cell));
    if (i < 0 || j < 0 || i >= columns || j >= rows) return 0;
    return flags[static_cast<std::size_t>(j * columns + i)];
  }
  static std::vector<Point2> centres_of(const std::vector<PlaneCircle>& circles) {
    std::vector<Point2> out;
    for (const PlaneCircle& c : circles) out.push_back(c.centre);
    return out;
  }
};

PlaneSpacing::PlaneSpacing(const std::vector<PlaneCircle>& circles, const SizingField& sizing, double lipschitz,
                           double largest, const Eigen::AlignedBox2d& frame)
    : impl_(std::make_shared<Impl>(circles, sizing, lipschitz, largest, frame)) {}

double PlaneSpacing::operator()(const Point2& x) const {
  const Impl& m = *impl_;
  double best = std::min(m.largest, m.sizing(Point(x.x(), x.y(), 0)));
  if (m.flags_at(x) & Impl::kCapped) return best;
  // Far from every circle, the nearest one's distance alone shows the bound holds.
  std::uint32_t nearest;
  double squared;
  if (m.tree.nearest(x, 1, &nearest, &squared) == 0) return best;
  if (m.smallest + m.lipschitz * std::sqrt(squared) >= best) return best;
  constexpr std::size_t kNearest = 16;
  std::uint32_t index[kNearest];
  double sq[kNearest];
  const std::size_t found = m.tree.nearest(x, kNearest, index, sq);
  for (std::size_t k = 0; k < found; ++k) best = std::min(best, m.radii[index[k]] + m.lipschitz * std::sqrt(sq[k]));
  return best;
}

bool PlaneSpacing::in_clearance(const Point2& x) const {
  const Impl& m = *impl_;
  if (m.flags_at(x) & Impl::kClear) return false;
  const double factor = kPlaneClearance;
  std::uint32_t nearest;
  double squared;
  if (m.tree.nearest(x, 1, &nearest, &squared) == 0) return false;
  if (squared >= factor * factor * m.widest * m.widest) return false;
  thread_local std::vector<std::uint32_t> near;
  m.tree.within(x, factor * m.widest, near);
  return std::any_of(near.begin(), near.end(), [&](std::uint32_t c) { return (x - m.centres[c]).norm() < factor * m.radii[c]; });
}

double PlaneSpacing::lipschitz() const { return impl_->lipschitz; }

namespace {

// Seeds by spacing level: a seed of spacing t sits in the grid of cells 2^floor(log2 t) wide,
// so a query looks at a few cells of the few levels a Lipschitz spacing allows nearby.
class DiskGrid {
 public:
  DiskGrid(double lipschitz, const Eigen::AlignedBox2d& frame) : lipschitz_(std::min(lipschitz, 0.9)), frame_(frame) {}

  void insert(const Point2& p, double spacing) {
    Level& level = level_for(level_of(spacing));
    const auto index = static_cast<std::uint32_t>(points_.size());
    points_.push_back(p);
    std::uint32_t& head = level.head(cell_at(p.x() - frame_.min().x(), level.cell), cell_at(p.y() - frame_.min().y(), level.cell));
    next_.push_back(head);
    head = index;
  }
  // Whether a seed lies nearer p than `spacing`: seeds of a Lipschitz spacing that near have
  // spacings within the Lipschitz constant of it, so only those levels are looked at.
  bool conflicts(const Point2& p, double spacing) const {
    const int lo = level_of((1 - lipschitz_) * spacing), hi = level_of((1 + lipschitz_) * spacing);
    const Point2 q = p - frame_.min();
    for (int l = lo; l <= hi; ++l) {
      const auto it = levels_.find(l);
      if (it == levels_.end()) continue;
      const Level& level = it->second;
      const std::int64_t x0 = cell_at(q.x() - spacing, level.cell), x1 = cell_at(q.x() + spacing, level.cell);
      const std::int64_t y0 = cell_at(q.y() - spacing, level.cell), y1 = cell_at(q.y() + spacing, level.cell);
      for (std::int64_t i = x0; i <= x1; ++i) {
        for (std::int64_t j = y0; j <= y1; ++j) {
          for (std::uint32_t s = level.first(i, j); s != kEnd; s = next_[s]) {
            if ((points_[s] - p).squaredNorm() < spacing * spacing) return true;
          }
        }
      }
    }
    return false;
  }

 private:
  static constexpr std::uint32_t kEnd = static_cast<std::uint32_t>(-1);
  // The seeds of one level by cell: an array over the frame where it is small enough, else a
  // hash of the cells in use.
  struct Level {
    double cell = 0;
    std::int64_t columns = 0, rows = 0;
    std::vector<std::uint32_t> flat;
    std::unordered_map<std::uint64_t, std::uint32_t> hashed;
    std::uint32_t& head(std::int64_t i, std::int64_t j) {
      if (!flat.empty()) return flat[static_cast<std::size_t>(std::clamp<std::int64_t>(j, 0, rows - 1) * columns + std::clamp<std::int64_t>(i, 0, columns - 1))];
      return hashed.try_emplace(pack(i, j), kEnd).first->second;
    }
    std::uint32_t first(std::int64_t i, std::int64_t j) const {
      if (!flat.empty()) {
        if (i < 0 || j < 0 || i >= columns || j >= rows) return kEnd;
        return flat[static_cast<std::size_t>(j * columns + i)];
      }
      const auto it = hashed.find(pack(i, j));
      return it == hashed.end() ? kEnd : it->second;
    }
  };
  Level& level_for(int l) {
    const auto [it, fresh] = levels_.try_emplace(l);
    Level& level = it->second;
    if (fresh) {
      level.cell = std::ldexp(1.0, l);
      const double columns = std::ceil(frame_.sizes().x() / level.cell) + 1, rows = std::ceil(frame_.sizes().y() / level.cell) + 1;
      if (columns * rows <= kFlatCells) {
        level.columns = static_cast<std::int64_t>(columns);
        level.rows = static_cast<std::int64_t>(rows);
        level.flat.assign(static_cast<std::size_t>(columns * rows), kEnd);
      }
    }
    return level;
  }
  static constexpr double kFlatCells = 1 << 24;
  static int level_of(double spacing) { return std::ilogb(spacing); }
  static std::int64_t cell_at(double x, double cell) { return static_cast<std::int64_t>(std::floor(x / cell)); }
  static std::uint64_t pack(std::int64_t i, std::int64_t j) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(i)) << 32) | static_cast<std::uint32_t>(j);
  }
  double lipschitz_;
  Eigen::AlignedBox2d frame_;
  std::vector<Point2> points_;
  std::vector<std::uint32_t> next_;
  std::unordered_map<int, Level> levels_;
};

constexpr int kTries = 12;

}  // namespace

std::vector<Seed> sample_plane(const std::vector<Seed>& boundary, const PlaneSpacing& spacing,
                               const Eigen::AlignedBox2d& frame, InteriorMode mode, double lattice_spacing,
                               std::uint64_t seed) {
  DiskGrid grid(spacing.lipschitz(), frame);
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
    return frame.contains(q) && !spacing.in_clearance(q) && !grid.conflicts(q, t);
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
