// The cells of seeds cut one at a time, each from a cube about its seed by its nearest seeds in
// order (compute_voronoi_cells, recompute_voronoi_cells), and the checks on cells so cut.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <voro++.hh>

#include "cells/raw_cell_extract.hpp"
#include "cells/voronoi_cells.hpp"
#include "geometry/curve_order.hpp"
#include "geometry/point_cloud.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust::cells {
namespace {

// Seeds the first shell of a cutter's first cell holds (later cells fetch as far as the cell
// before them needed): most cells need fewer.
constexpr std::size_t kNearestFirst = 32;
// Candidates of a shell sorted first; each next chunk is twice the one before.
constexpr std::size_t kFirstChunk = 64;
// Half the side of the first cube of a cell cut at the scale of its nearest seed, in that unit.
constexpr double kLocalCube = 64;
// A cell whose farthest vertex lies nearer its seed than 2^-6 frame units is cut again at its
// local scale: Voro++'s plane tolerance there stands for more than 1e-8 of the cell's size.
// (Voro++ keeps vertices at twice their coordinates, and so the squared radius at four times.)
constexpr double kTinyCell2 = 4.0 / 4096;
// Cubes a cell Voro++ leaves broken is cut from, each this much bigger than the last.
constexpr int kWholeTries = 4;
constexpr double kWholeGrowth = 1.375;

using Cloud = PointCloudAdaptor<Point, IdentityPosition>;

}  // namespace

std::vector<RawCell> compute_voronoi_cells(const std::vector<Point>& positions, const std::vector<Index>& cell_seeds) {
  std::vector<RawCell> cells(cell_seeds.size());
  std::vector<std::size_t> all(cell_seeds.size());
  std::iota(all.begin(), all.end(), std::size_t{0});
  recompute_voronoi_cells(positions, cell_seeds, all, 0, cells);
  return cells;
}

namespace {

// Cuts and extracts one cell: a cube about its seed, cut by the other
// seeds in the order of (distance, seed), each cut unless it lies beyond twice the cell's
// farthest vertex, where it cannot cut, nor can any after it. The seeds come from k-d tree
// searches in shells about the seed, each shell every seed at a squared distance in [lower,
// upper). So the cuts that are made do not depend on the tree, nor on where the shells end (which
// is all a cutter carries from one cell to the next), nor on seeds beyond the reach, whatever
// else the positions hold.
class CellCutter {
 public:
  CellCutter(const std::vector<Point>& positions, const StaticKdTree<Cloud>& tree) : positions_(positions), tree_(tree) {}

  // `reach`: half the side of the cube bigger than all seeds; `variant` scales it (and the local
  // cube) by 1.375^variant. `at_local_scale`: see below. `first`: seeds to cut by before all
  // others, those whose cuts an earlier try lost.
  void cut(Index seed, double reach, int variant, bool at_local_scale, RawCell& out,
           const std::vector<std::uint32_t>& first = {}) {
    first_cuts_ = first;
    const double growth = std::pow(1.375, variant);
    // Voro++ decides what lies on a plane with an absolute tolerance, which the frame sets to
    // about 1e-11 of the seed spacing. Where seeds crowd far closer than the mean (a thin part of
    // a model), a plane that cuts a thin wedge from a tiny cell can pass for one through its
    // vertices. At local scale, a cell is cut in units of its nearest seed's distance instead (a
    // power of two, so exact) from a cube of kLocalCube such units; a cell that keeps a wall of it
    // is cut as elsewhere (a cube of the frame's units so big would lose cuts to round-off). Only
    // the assembly's fallbacks do so: neighbours cut at two scales round their shared vertices
    // apart.
    const double scale = at_local_scale ? local_scale(seed) : 1;
    if (scale < 1 && cut_at_scale(seed, growth, scale, out)) return;
    cut_from(seed, reach * growth, 1, out);
    // Voro++'s tolerance is absolute on the plane test (1e-11 on |d|^2 - x.d, in squared units):
    // for a cell far smaller than the frame's unit it stands for a distance that is no longer
    // negligible beside the cell (a cell 1e-4 units across, among nearly cospherical seeds, kept
    // a face 1e-5 across toward a seed another one 1.2e-8 nearer should have cut, and its
    // neighbours never agreed on it). Such a cell is cut again in units of its own size (a power
    // of two, so exact), from a cube that holds it.
    if (!at_local_scale && radius2_ < kTinyCell2) {
      const double size = std::exp2(std::round(std::log2(std::sqrt(radius2_) / 2)));
      if (!cut_at_scale(seed, growth, size, out)) cut_from(seed, reach * growth, 1, out);
    }
  }

 private:
  // Collects the seeds at squared distances in [lower, upper) as (squared distance, seed), and
  // counts those below upper.
  class Shell {
   public:
    using DistanceType = double;
    using IndexType = std::uint32_t;
    Shell(double lower, double upper, std::vector<std::pair<double, std::uint32_t>>& out)
        : lower_(lower), upper_(upper), out_(out) {}
    bool full() const { return true; }
    bool addPoint(double d2, std::uint32_t seed) {
      if (d2 < upper_) {
        ++within_;
        if (d2 >= lower_) out_.emplace_back(d2, seed);
      }
      return true;
    }
    // A little beyond upper, for the tree's pruning only: it rounds the distance to a node's box,
    // and a seed just inside the shell must not be lost to that (addPoint keeps the exact bounds).
    double worstDist() const { return upper_ * (1 + 1e-12); }
    std::size_t within() const { return within_; }

   private:
    double lower_, upper_;
    std::vector<std::pair<double, std::uint32_t>>& out_;
    std::size_t within_ = 0;
  };

  // The cell cut at `scale` from a cube of kLocalCube such units; false, leaving `out` cut so,
  // when the cell keeps a wall of that cube (a cube of the frame's units would then do better).
  bool cut_at_scale(Index seed, double growth, double scale, RawCell& out) {
    cut_from(seed, kLocalCube * growth, scale, out);
    return std::none_of(out.neighbours.begin(), out.neighbours.end(), [](std::int32_t n) { return n < 0; });
  }

  // The cell cut from the cube of half-side `half_side` in units of `scale`. Where Voro++ leaves
  // the cell broken (edges_consistent), the same cuts from a bigger cube meet other vertices.
  void cut_from(Index seed, double half_side, double scale, RawCell& out) {
    for (int attempt = 0; attempt < kWholeTries; ++attempt, half_side *= kWholeGrowth) {
      if (cut_once(seed, half_side, scale, out)) return;
    }
    throw Error(Error::Kind::InvalidGeometry,
                "Voro++ cannot cut the cell of seed " + std::to_string(seed) + " whole from " +
                    std::to_string(kWholeTries) + " cubes: its neighbours are nearly cospherical; another --seed "
                    "places them differently");
  }

  // cut_from's one try; false when Voro++'s cell is not whole.
  bool cut_once(Index seed, double half_side, double scale, RawCell& out) {
    const Point& p = positions_[seed];
    const double scale2 = scale * scale, inverse = 1 / scale;  // powers of two: exact
    cell_.init(-half_side, half_side, -half_side, half_side, -half_side, half_side);
    measure_cell();
    double reach2 = 0;  // the farthest seed tried, squared
    // A cut lost to round-off among nearly cospherical seeds is lost in the same way whatever the
    // cube; made before the others, where no vertex lies near its plane yet, it holds. (Its seed
    // lies within twice the farthest vertex, so `reach2` covers it.)
    for (const std::uint32_t other : first_cuts_) {
      const Point d = (positions_[other] - p) * inverse;
      if (misses_cell(d)) continue;
      cell_.nplane(d.x(), d.y(), d.z(), d.squaredNorm(), static_cast<int>(other));
      measure_cell();
    }
    // Nearest first, a chunk at a time, each chunk twice the last: a shell guessed from the cell
    // before can hold a thousand times the seeds this one needs (where a crowd of tiny seeds sits
    // beside big cells: on igl_camelhead 2 158 a cell, half a million for some), and sorting them
    // all cost more than the cutting. The order of the cuts is that of a full sort.
    const auto cut_in_order = [&](std::vector<std::pair<double, std::uint32_t>>& candidates) {
      std::size_t chunk = kFirstChunk;
      for (auto begin = candidates.begin(); begin != candidates.end(); chunk *= 2) {
        const auto end = candidates.end() - begin > static_cast<std::ptrdiff_t>(chunk)
                             ? begin + static_cast<std::ptrdiff_t>(chunk)
                             : candidates.end();
        if (end != candidates.end()) std::nth_element(begin, end, candidates.end());
        std::sort(begin, end);
        for (; begin != end; ++begin) {
          const auto& [d2, other] = *begin;
          if (other == seed) continue;
          if (d2 > radius2_ * scale2) return false;
          if (std::find(first_cuts_.begin(), first_cuts_.end(), other) != first_cuts_.end()) continue;
          reach2 = d2;
          const Point d = (positions_[other] - p) * inverse;
          if (misses_cell(d)) continue;
          cell_.nplane(d.x(), d.y(), d.z(), d.squaredNorm(), static_cast<int>(other));
          measure_cell();
        }
      }
      return true;
    };
    // Seeds in shells about the seed, nearest first. The first shell reaches as far as the last
    // cell cut needed (neighbouring cells in a run are alike in size); each next one twice as far
    // as the one before, but no further than this cell needs. Where the cuts stop does not depend
    // on the shells, only how many searches find the seeds.
    double lower = 0;  // every seed nearer than this (squared) has had its turn
    const double first = guess2_ > 0 ? guess2_ : first_shell2(p);
    for (bool more = true; more && lower <= radius2_ * scale2;) {
      const double bound2 = std::nextafter(radius2_ * scale2, std::numeric_limits<double>::infinity());
      const double upper = std::min(bound2, lower > 0 ? std::max(4 * lower, 1e-300) : first);
      order_.clear();
      Shell shell(lower, upper, order_);
      tree_.findNeighbors(shell, p.data(), nanoflann::SearchParams(32, 0, false));
      more = cut_in_order(order_) && shell.within() < positions_.size();
      lower = upper;
    }
    if (!extract(cell_, p, out, scratch_, scale)) return false;
    out.reach2 = std::max(reach2, radius2_ * scale2);
    if (scale == 1) guess2_ = radius2_;
    return true;
  }

  // For a cell with no cell cut before it: just beyond the squared distance of the
  // kNearestFirst-th seed, so that the first shell holds it and any at the same distance.
  double first_shell2(const Point& p) {
    const std::size_t found = nearest_seeds(p);
    return found > 0 ? std::nextafter(scratch_.distance2[found - 1], std::numeric_limits<double>::infinity()) : 1e-300;
  }

  // The kNearestFirst seeds nearest p (or all), into scratch_.near and .distance2; how many.
  std::size_t nearest_seeds(const Point& p) {
    const std::size_t wanted = std::min<std::size_t>(kNearestFirst, positions_.size());
    scratch_.near.resize(wanted);
    scratch_.distance2.resize(wanted);
    return tree_.knnSearch(p.data(), wanted, scratch_.near.data(), scratch_.distance2.data());
  }

  // The bounding box of the cell's vertices and Voro++'s max_radius_squared, after each cut.
  // Voro++ keeps vertices at twice their coordinates; so does the box.
  void measure_cell() {
    radius2_ = cell_.max_radius_squared();
    box_lo_ = box_hi_ = Point(cell_.pts[0], cell_.pts[1], cell_.pts[2]);
    for (int v = 1; v < cell_.p; ++v) {
      const Point x(cell_.pts[3 * v], cell_.pts[3 * v + 1], cell_.pts[3 * v + 2]);
      box_lo_ = box_lo_.cwiseMin(x);
      box_hi_ = box_hi_.cwiseMax(x);
    }
  }

  // Whether the plane halfway to the seed at offset d leaves every vertex clearly on the seed's
  // side, so that cutting would change nothing: most seeds within twice the farthest vertex miss
  // a flat cell, and Voro++ would climb over its vertices to find that out. The box rules out
  // most; Voro++ takes a vertex within 1e-11 of a plane to lie on it, and the margin is far wider.
  bool misses_cell(const Point& d) const {
    const double r2 = d.squaredNorm();
    const double limit = r2 * (1 - 1e-9) - 1e-9;
    double support = 0;
    for (int k = 0; k < 3; ++k) support += std::max(d[k] * box_lo_[k], d[k] * box_hi_[k]);
    if (support < limit) return true;
    const double* x = cell_.pts;
    for (int v = 0; v < cell_.p; ++v, x += 3) {
      if (d[0] * x[0] + d[1] * x[1] + d[2] * x[2] >= limit) return false;
    }
    return true;
  }

  // The power of two nearest the distance to the nearest other seed, at most 1 (the frame's
  // spacing): a seed added nearer than that is within the cell's reach, so the scale of a cell
  // that cells_reached passes over stays as it was.
  double local_scale(Index seed) {
    const std::size_t found = nearest_seeds(positions_[seed]);
    for (std::size_t j = 0; j < found; ++j) {
      if (scratch_.near[j] == seed || !(scratch_.distance2[j] > 0)) continue;
      return std::min(1.0, std::exp2(std::round(std::log2(scratch_.distance2[j]) / 2)));
    }
    return 1;
  }

  const std::vector<Point>& positions_;
  const StaticKdTree<Cloud>& tree_;
  voro::voronoicell_neighbor cell_;
  Scratch scratch_;
  std::vector<std::pair<double, std::uint32_t>> order_;
  double radius2_ = 0;
  double guess2_ = 0;  // the squared reach the last cell cut at scale 1 needed
  Point box_lo_, box_hi_;
  std::vector<std::uint32_t> first_cuts_;  // see cut()
};

// The seeds nearer than its own to a vertex of `cell`, beyond round-off (1e-6 of its distance,
// far above what degenerate vertices differ by), added to `inside`; whether there is none. Where
// many seeds are nearly cospherical, Voro++ 0.4.6 can lose a whole cut to round-off in an
// earlier one, and the cell keeps a wedge of its neighbour's.
bool holds_only_its_own(const std::vector<Point>& positions, const StaticKdTree<Cloud>& tree, Index seed,
                        const RawCell& cell, std::vector<std::uint32_t>* inside = nullptr) {
  const Point& p = positions[seed];
  bool only = true;
  for (const Point& x : cell.vertices) {
    std::uint32_t nearest = 0;
    double nearest2 = 0;
    tree.knnSearch(x.data(), 1, &nearest, &nearest2);
    const double own2 = (x - p).squaredNorm();
    if (nearest == seed || !(nearest2 < own2 * (1 - 2e-6))) continue;
    only = false;
    if (!inside) break;
    if (std::find(inside->begin(), inside->end(), nearest) == inside->end()) inside->push_back(nearest);
  }
  return only;
}

// Initial cube sizes a cell that failed holds_only_its_own is cut from, one after the other.
constexpr int kVerifiedTries = 8;

}  // namespace

SeedTree::SeedTree(const std::vector<Point>& positions)
    : cloud{&positions}, tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {
  Eigen::AlignedBox3d bounds;
  for (const Point& p : positions) bounds.extend(p);
  // A cube about a seed this big holds all seeds, so that only a cell no seed bounds keeps one of
  // its walls.
  half_side = bounds.diagonal().norm() + 1;
}

void recompute_voronoi_cells(const std::vector<Point>& positions, const std::vector<Index>& cell_seeds,
                             const std::vector<std::size_t>& which, int variant, std::vector<RawCell>& cells,
                             const SeedTree* seed_tree) {
  if (which.empty()) return;
  std::optional<SeedTree> own;
  if (!seed_tree) seed_tree = &own.emplace(positions);
  const StaticKdTree<Cloud>& tree = seed_tree->tree;
  const double base = seed_tree->half_side;
  // Cut along a curve through the seeds: a cutter's next cell is mostly a neighbour of its last,
  // like it in size (the first shell of seeds it fetches) and in the tree nodes it visits.
  const std::vector<std::uint32_t> along = geometry::curve_order(
      which.size(), [&](std::size_t k) -> const Point& { return positions[cell_seeds[which[k]]]; });
  std::vector<Index> unbounded(which.size(), std::numeric_limits<Index>::max());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, which.size(), 256), [&](const auto& range) {
    CellCutter cutter(positions, tree);
    for (std::size_t j = range.begin(); j != range.end(); ++j) {
      const std::size_t k = along[j];
      const Index seed = cell_seeds[which[k]];
      RawCell& out = cells[which[k]];
      cutter.cut(seed, base, variant, false, out);
      // Variants other than 0 are the assembly's fallbacks: a cell there is checked, and cut at
      // local scale and from other cubes, the seeds of the cuts lost so far first, until it holds
      // nothing of another seed's. (On igl_camelhead at --sharp-angle 60, a cell among nearly
      // cospherical seeds lost the same cut from every cube, and kept a vertex 40 % nearer that
      // seed than its own.)
      std::vector<std::uint32_t> lost_cuts;
      for (int t = 1; variant > 0 && t < kVerifiedTries && !holds_only_its_own(positions, tree, seed, out, &lost_cuts); ++t) {
        cutter.cut(seed, base, variant + (t / 2) * 4, t % 2 == 1, out, lost_cuts);
      }
      for (const std::int32_t n : out.neighbours) {
        if (n < 0) unbounded[k] = seed;
      }
    }
  });
  const Index worst = *std::min_element(unbounded.begin(), unbounded.end());
  if (worst != std::numeric_limits<Index>::max()) {
    throw Error(Error::Kind::InvalidGeometry,
                "cell of seed " + std::to_string(worst) + " is not bounded by seeds: the seeds do not enclose the "
                "materials (seeds of no material must surround them)");
  }
}

std::vector<std::size_t> cells_holding_others(const std::vector<Point>& positions, const std::vector<Index>& cell_seeds,
                                              const std::vector<RawCell>& cells, const std::vector<std::size_t>& which,
                                              const SeedTree* seed_tree) {
  std::optional<SeedTree> own;
  if (!seed_tree) seed_tree = &own.emplace(positions);
  const StaticKdTree<Cloud>& tree = seed_tree->tree;
  std::vector<char> bad(which.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, which.size(), 64), [&](const auto& range) {
    for (std::size_t k = range.begin(); k != range.end(); ++k) {
      bad[k] = !holds_only_its_own(positions, tree, cell_seeds[which[k]], cells[which[k]]);
    }
  });
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < which.size(); ++k) {
    if (bad[k]) out.push_back(which[k]);
  }
  return out;
}

std::vector<std::size_t> cells_reached(const std::vector<Point>& positions, const std::vector<Index>& cell_seeds,
                                       const std::vector<RawCell>& cells, const std::vector<Index>& added) {
  std::vector<Point> added_positions;
  for (Index s : added) added_positions.push_back(positions[s]);
  const Cloud cloud{&added_positions};
  StaticKdTree<Cloud> tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(8));
  std::vector<char> reached(cells.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cells.size(), 512), [&](const auto& range) {
    std::vector<std::pair<std::uint32_t, double>> near;
    for (std::size_t c = range.begin(); c != range.end(); ++c) {
      const Point& p = positions[cell_seeds[c]];
      near.clear();
      reached[c] = tree.radiusSearch(p.data(), cells[c].reach2 * (1 + 1e-9) + 1e-12, near, nanoflann::SearchParams()) > 0;
    }
  });
  std::vector<std::size_t> out;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    if (reached[c]) out.push_back(c);
  }
  return out;
}

}  // namespace vorocrust::cells
