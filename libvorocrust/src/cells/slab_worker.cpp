// The cells of many seeds cut in Voro++'s containers, a slab of seeds along one axis at a time
// (compute_voronoi_cells_in_containers).
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <voro++.hh>

#include "cells/raw_cell_extract.hpp"
#include "cells/voronoi_cells.hpp"

namespace vorocrust::cells {
namespace {

// Cells per slab: enough for containers to pay off, few enough that two threads share the work
// evenly; fixed, so that the result does not depend on the thread count.
constexpr std::size_t kSlabCells = 8192;
// Voro++'s own estimate of the best number of seeds per block of its grid.
constexpr double kSeedsPerBlock = 5.6;
// First margin of neighbouring seeds around a slab, in units of the seed spacing.
constexpr double kFirstMargin = 3.0;


// The seeds sorted along the axis that the slabs cut, and the bounds of the container.
struct Layout {
  int axis = 0;
  Eigen::AlignedBox3d bounds;          // of all seeds
  std::vector<Index> sorted;           // seed indices by coordinate along `axis`
  std::vector<double> sorted_value;    // their coordinates along `axis`
};

Layout make_layout(const std::vector<Point>& positions) {
  Layout l;
  for (const Point& p : positions) l.bounds.extend(p);
  Eigen::Index axis = 0;
  l.bounds.sizes().maxCoeff(&axis);
  l.axis = static_cast<int>(axis);
  l.sorted.resize(positions.size());
  std::iota(l.sorted.begin(), l.sorted.end(), Index{0});
  std::sort(l.sorted.begin(), l.sorted.end(), [&](Index a, Index b) {
    const double va = positions[a][l.axis], vb = positions[b][l.axis];
    return va < vb || (va == vb && a < b);
  });
  l.sorted_value.resize(positions.size());
  for (std::size_t k = 0; k < l.sorted.size(); ++k) l.sorted_value[k] = positions[l.sorted[k]][l.axis];
  return l;
}

// A Voro++ container's box and grid.
struct Box {
  Point lower, upper;
  int blocks[3];
};

class SlabWorker {
 public:
  SlabWorker(const std::vector<Point>& positions, const Layout& layout) : positions_(positions), layout_(layout) {}

  // Computes the cells of `pending` (indices into cell_seeds), writing out[entry], or marking
  // lost[entry] where Voro++ gives no cell or one that keeps a wall of the container.
  void run(const std::vector<Index>& cell_seeds, std::vector<std::size_t> pending, std::vector<RawCell>& out,
           std::vector<char>& lost) {
    const int a = layout_.axis;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t e : pending) {
      lo = std::min(lo, positions_[cell_seeds[e]][a]);
      hi = std::max(hi, positions_[cell_seeds[e]][a]);
    }
    double margin = kFirstMargin;
    while (!pending.empty()) {
      const double range_lo = std::max(layout_.bounds.min()[a], lo - margin);
      const double range_hi = std::min(layout_.bounds.max()[a], hi + margin);
      const bool open_lo = range_lo > layout_.bounds.min()[a], open_hi = range_hi < layout_.bounds.max()[a];
      const Box box = container_box(range_lo, range_hi);
      voro::container con(box.lower.x(), box.upper.x(), box.lower.y(), box.upper.y(), box.lower.z(), box.upper.z(),
                          box.blocks[0], box.blocks[1], box.blocks[2], false, false, false, 8);
      voro::particle_order order;
      fill(con, order, range_lo, range_hi, cell_seeds, pending);
      std::vector<std::size_t> retry;
      double needed = 0;
      for (std::size_t k = 0; k < pending.size(); ++k) {
        const Index seed = cell_seeds[pending[k]];
        if (!con.compute_cell(cell_, order.o[2 * k], order.o[2 * k + 1])) {
          lost[pending[k]] = 1;
          continue;
        }
        RawCell& cell = out[pending[k]];
        extract(cell_, positions_[seed], cell, scratch_);
        // The empty sphere of every vertex must lie within the seeds the container holds.
        bool complete = true;
        for (const Point& v : cell.vertices) {
          const double r = (v - positions_[seed]).norm();
          if (open_lo && v[a] - r < range_lo) complete = false, needed = std::max(needed, lo - (v[a] - r));
          if (open_hi && v[a] + r > range_hi) complete = false, needed = std::max(needed, v[a] + r - hi);
        }
        if (!complete) {
          retry.push_back(pending[k]);
          continue;
        }
        if (std::any_of(cell.neighbours.begin(), cell.neighbours.end(), [](std::int32_t n) { return n < 0; })) {
          lost[pending[k]] = 1;
        }
      }
      pending.swap(retry);
      margin = std::max(2 * margin, 1.25 * needed);
    }
  }

 private:
  // The seeds with coordinates in [range_lo, range_hi] along the axis.
  std::pair<std::size_t, std::size_t> in_range(double range_lo, double range_hi) const {
    const auto& v = layout_.sorted_value;
    return {static_cast<std::size_t>(std::lower_bound(v.begin(), v.end(), range_lo) - v.begin()),
            static_cast<std::size_t>(std::upper_bound(v.begin(), v.end(), range_hi) - v.begin())};
  }

  Box container_box(double range_lo, double range_hi) const {
    const int a = layout_.axis;
    const auto [first, last] = in_range(range_lo, range_hi);
    // One unit of room beyond the outermost seeds, so that none sits on a wall.
    Box box{layout_.bounds.min() - Point::Ones(), layout_.bounds.max() + Point::Ones(), {1, 1, 1}};
    box.lower[a] = range_lo - 1;
    box.upper[a] = range_hi + 1;
    const Point size = box.upper - box.lower;
    const double block = std::cbrt(size.prod() * kSeedsPerBlock / static_cast<double>(last - first));
    for (int d = 0; d < 3; ++d) box.blocks[d] = static_cast<int>(std::clamp(std::ceil(size[d] / block), 1.0, 1024.0));
    return box;
  }

  // Puts the seeds in range into the container, the cells to compute last and in `order`.
  void fill(voro::container& con, voro::particle_order& order, double range_lo, double range_hi,
            const std::vector<Index>& cell_seeds, const std::vector<std::size_t>& pending) const {
    const auto [first, last] = in_range(range_lo, range_hi);
    std::vector<Index> own(pending.size());
    for (std::size_t k = 0; k < pending.size(); ++k) own[k] = cell_seeds[pending[k]];
    std::sort(own.begin(), own.end());
    for (std::size_t k = first; k < last; ++k) {
      const Index s = layout_.sorted[k];
      if (std::binary_search(own.begin(), own.end(), s)) continue;
      const Point& p = positions_[s];
      con.put(static_cast<int>(s), p.x(), p.y(), p.z());
    }
    for (std::size_t e : pending) {
      const Index s = cell_seeds[e];
      const Point& p = positions_[s];
      con.put(order, static_cast<int>(s), p.x(), p.y(), p.z());
    }
  }

  const std::vector<Point>& positions_;
  const Layout& layout_;
  voro::voronoicell_neighbor cell_;
  Scratch scratch_;
};

}  // namespace

std::vector<RawCell> compute_voronoi_cells_in_containers(const std::vector<Point>& positions, const std::vector<Index>& cell_seeds,
                                                         std::vector<char>& lost) {
  std::vector<RawCell> out(cell_seeds.size());
  lost.assign(cell_seeds.size(), 0);
  if (cell_seeds.empty()) return out;
  const Layout layout = make_layout(positions);

  // Slabs: runs of kSlabCells cells in the order of their seeds along the axis.
  std::vector<std::size_t> by_axis(cell_seeds.size());
  std::iota(by_axis.begin(), by_axis.end(), std::size_t{0});
  std::sort(by_axis.begin(), by_axis.end(), [&](std::size_t x, std::size_t y) {
    const double vx = positions[cell_seeds[x]][layout.axis], vy = positions[cell_seeds[y]][layout.axis];
    return vx < vy || (vx == vy && x < y);
  });
  const std::size_t slabs = (cell_seeds.size() + kSlabCells - 1) / kSlabCells;
  tbb::parallel_for(std::size_t{0}, slabs, [&](std::size_t s) {
    const auto begin = by_axis.begin() + static_cast<std::ptrdiff_t>(s * kSlabCells);
    const auto end = by_axis.begin() + static_cast<std::ptrdiff_t>(std::min(by_axis.size(), (s + 1) * kSlabCells));
    SlabWorker worker(positions, layout);
    worker.run(cell_seeds, std::vector<std::size_t>(begin, end), out, lost);
  });
  return out;
}

}  // namespace vorocrust::cells
