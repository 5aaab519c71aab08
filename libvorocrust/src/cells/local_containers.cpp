// The cells of some seeds, each computed in a Voro++ container of its own that holds the seeds
// within its reach (compute_voronoi_cells_in_containers).
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <voro++.hh>

#include "cells/raw_cell_extract.hpp"
#include "cells/voronoi_cells.hpp"

namespace vorocrust::cells {
namespace {

// The first container of a cell holds its kNearest nearest seeds (and any as near as the last):
// most cells need no more.
constexpr std::size_t kNearest = 48;
// Voro++'s own estimate of the best number of seeds per block of its grid.
constexpr double kSeedsPerBlock = 5.6;
// A container's walls stand this much (relative) beyond the seeds it holds, so that none sits
// on a wall.
constexpr double kWallRoom = 0.01;

// One container per cell, not one for many: a container's grid is uniform, and where the
// spacing of the seeds varies by orders of magnitude (a thin feature of the surface in a wide
// box of interior seeds) a grid for them all puts thousands of seeds in a block and the cells
// there cost the square of that (igl_camelhead: more than ten minutes for the few cells at
// odds with a neighbour). The seeds within a cell's reach are alike in spacing.
class LocalContainer {
 public:
  LocalContainer(const std::vector<Point>& positions, const SeedTree& tree) : positions_(positions), tree_(tree) {}

  // The cell of `seed` in `out`; false where Voro++ gives no cell, or one that keeps a wall of a
  // container that holds every seed.
  bool compute(Index seed, RawCell& out) {
    const Point& p = positions_[seed];
    double reach = first_reach(p);
    for (;;) {
      near_.clear();
      const std::size_t found = tree_.tree.radiusSearch(p.data(), reach * reach, near_, nanoflann::SearchParams(32, 0, false));
      const bool holds_all = found >= positions_.size();
      if (!compute_among(seed, reach, out)) return false;
      // Every seed that could cut the cell lies within twice its farthest vertex.
      double farthest2 = 0;
      for (const Point& v : out.vertices) farthest2 = std::max(farthest2, (v - p).squaredNorm());
      const double needed = 2 * std::sqrt(farthest2) * (1 + 1e-9);
      if (needed <= reach || holds_all) {
        return std::none_of(out.neighbours.begin(), out.neighbours.end(), [](std::int32_t n) { return n < 0; });
      }
      reach = std::max(1.5 * reach, needed);
    }
  }

 private:
  // Just beyond the kNearest-th nearest seed.
  double first_reach(const Point& p) {
    const std::size_t wanted = std::min(kNearest, positions_.size());
    scratch_.near.resize(wanted);
    scratch_.distance2.resize(wanted);
    const std::size_t found = tree_.tree.knnSearch(p.data(), wanted, scratch_.near.data(), scratch_.distance2.data());
    return found > 0 && scratch_.distance2[found - 1] > 0 ? std::sqrt(scratch_.distance2[found - 1]) * (1 + 1e-9) : 1;
  }

  // The cell among the seeds near_ holds, in a cube of half-side `reach` (and a little room)
  // about its seed. The container works in units of a power of two near an eighth of the reach,
  // with the seed at the origin: Voro++'s plane tolerance is absolute, and a cell far smaller
  // than the frame's unit (the cutter cuts those at their own scale too) can make it lose track
  // of a cut, or fail.
  bool compute_among(Index seed, double reach, RawCell& out) {
    const Point& p = positions_[seed];
    const double scale = std::exp2(std::round(std::log2(reach / 8))), inverse = 1 / scale;  // exact
    const double half = reach * (1 + kWallRoom) * inverse;
    const double block = std::cbrt(std::pow(2 * half, 3) * kSeedsPerBlock / static_cast<double>(near_.size()));
    const int blocks = static_cast<int>(std::clamp(std::ceil(2 * half / block), 1.0, 64.0));
    voro::container con(-half, half, -half, half, -half, half, blocks, blocks, blocks, false, false, false, 8);
    for (const auto& [other, d2] : near_) {
      if (other == seed) continue;
      const Point q = (positions_[other] - p) * inverse;
      con.put(static_cast<int>(other), q.x(), q.y(), q.z());
    }
    voro::particle_order order;
    con.put(order, static_cast<int>(seed), 0, 0, 0);
    if (order.op == order.o || !con.compute_cell(cell_, order.o[0], order.o[1])) return false;
    return extract(cell_, p, out, scratch_, scale);
  }

  const std::vector<Point>& positions_;
  const SeedTree& tree_;
  voro::voronoicell_neighbor cell_;
  Scratch scratch_;
  std::vector<std::pair<std::uint32_t, double>> near_;
};

}  // namespace

std::vector<RawCell> compute_voronoi_cells_in_containers(const std::vector<Point>& positions, const std::vector<Index>& cell_seeds,
                                                         const SeedTree& tree, std::vector<char>& lost) {
  std::vector<RawCell> out(cell_seeds.size());
  lost.assign(cell_seeds.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cell_seeds.size(), 16), [&](const auto& range) {
    LocalContainer container(positions, tree);
    for (std::size_t k = range.begin(); k != range.end(); ++k) {
      if (!container.compute(cell_seeds[k], out[k])) lost[k] = 1;
    }
  });
  return out;
}

}  // namespace vorocrust::cells
