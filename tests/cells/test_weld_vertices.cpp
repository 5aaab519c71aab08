// Welding the vertices of raw cells: a tolerance per cell, raised where cells disagree, welds
// there and nowhere else.
#include <gtest/gtest.h>

#include <random>

#include "cells/voronoi_cells.hpp"
#include "cells/weld_vertices.hpp"
#include "vorocrust/cells.hpp"

namespace vorocrust {
namespace {

// A cubic lattice of unit spacing moved by up to `jitter`: each cube corner, where eight cells
// meet, splits into Voronoi vertices about `jitter` apart.
struct JitteredLattice {
  cells::Frame frame;
  std::vector<Index> cell_seeds;  // the seeds away from the lattice's faces
  std::vector<cells::RawCell> raw;
};

JitteredLattice jittered_lattice(int n, double jitter) {
  JitteredLattice l;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> move(-jitter, jitter);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        const bool inner = i > 0 && i < n - 1 && j > 0 && j < n - 1 && k > 0 && k < n - 1;
        if (inner) l.cell_seeds.push_back(static_cast<Index>(l.frame.original.size()));
        l.frame.original.emplace_back(i + move(rng), j + move(rng), k + move(rng));
      }
    }
  }
  l.frame.normalized = l.frame.original;  // centre 0, scale 1: the lattice's spacing
  l.raw = cells::compute_voronoi_cells(l.frame.normalized, l.cell_seeds);
  return l;
}

std::vector<std::int32_t> cell_of_seed(const JitteredLattice& l) {
  std::vector<std::int32_t> of(l.frame.original.size(), kNoCell);
  for (std::size_t c = 0; c < l.cell_seeds.size(); ++c) of[l.cell_seeds[c]] = static_cast<std::int32_t>(c);
  return of;
}

// The welded points with x below `x` (or above, when `below` is false).
std::size_t points_on_side(const cells::WeldedVertices& w, double x, bool below) {
  std::size_t count = 0;
  for (const Point& p : w.points) count += below ? p.x() < x : p.x() > x;
  return count;
}

TEST(WeldVertices, EachCellWeldsAtItsOwnTolerance) {
  const int n = 8;
  const JitteredLattice l = jittered_lattice(n, 1e-7);
  const std::vector<std::int32_t> of = cell_of_seed(l);
  const std::size_t cells = l.cell_seeds.size();
  const auto weld = [&](double left, double right) {
    std::vector<double> tolerance(cells);
    // Cells of seeds with x up to n/2 - 1 on the left, their points reaching to x = n/2 - 1/2.
    for (std::size_t c = 0; c < cells; ++c) tolerance[c] = l.frame.original[l.cell_seeds[c]].x() < n / 2.0 - 0.5 ? left : right;
    return cells::weld_vertices(l.raw, l.cell_seeds, of, l.frame, tolerance);
  };
  // At 1e-9 the split corners stay apart; at 1e-5 each cube corner is one point.
  const cells::WeldedVertices fine = weld(1e-9, 1e-9), coarse = weld(1e-5, 1e-5), mixed = weld(1e-5, 1e-9);
  const double left = n / 2.0 - 1.5, right = n / 2.0 + 0.5;  // clear of the other side's cells
  ASSERT_GT(points_on_side(fine, left, true), points_on_side(coarse, left, true));
  ASSERT_GT(points_on_side(fine, right, false), points_on_side(coarse, right, false));
  // Welded coarsely where those cells ask for it, finely elsewhere.
  EXPECT_EQ(points_on_side(mixed, left, true), points_on_side(coarse, left, true));
  EXPECT_EQ(points_on_side(mixed, right, false), points_on_side(fine, right, false));
  // Every instance of a cell has a point, whatever the tolerances.
  for (const cells::WeldedVertices* w : {&fine, &coarse, &mixed}) {
    ASSERT_EQ(w->point_of.size(), w->first_instance.back());
    for (Index p : w->point_of) ASSERT_LT(p, w->points.size());
  }
}

}  // namespace
}  // namespace vorocrust
