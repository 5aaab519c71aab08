// The cells in Voro++'s containers, the assembly's first fallback: the same cells as cut alone,
// and a cell Voro++ cuts away to nothing flagged as lost, for the caller to keep the cell it had,
// rather than ending the run.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

#include "cells/seed_sets.hpp"
#include "cells/voronoi_cells.hpp"

namespace vorocrust {
namespace {

std::vector<Point> jittered_lattice(int n) {
  std::vector<Point> positions;
  for (const Seed& s : test::lattice_seeds(n, 0.3, [](const Point&) { return 1; })) positions.push_back(s.position);
  return positions;
}

void expect_containers_give_the_cells_cut_alone(const std::vector<Point>& positions, const std::vector<Index>& inner) {
  std::vector<char> lost;
  const cells::SeedTree tree(positions);
  const std::vector<cells::RawCell> in_containers =
      cells::compute_voronoi_cells_in_containers(positions, inner, tree, lost);
  const std::vector<cells::RawCell> alone = cells::compute_voronoi_cells(positions, inner);
  ASSERT_EQ(lost, std::vector<char>(inner.size(), 0));
  for (std::size_t k = 0; k < inner.size(); ++k) {
    EXPECT_EQ(in_containers[k].neighbours, alone[k].neighbours) << "seed " << inner[k];
    // The vertices as sets: both lists are sorted, but vertices above one another sort by
    // round-off in x.
    ASSERT_EQ(in_containers[k].vertices.size(), alone[k].vertices.size()) << "seed " << inner[k];
    for (const Point& v : alone[k].vertices) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const Point& w : in_containers[k].vertices) nearest = std::min(nearest, (v - w).norm());
      EXPECT_LT(nearest, 1e-12) << "seed " << inner[k];
    }
  }
}

TEST(VoronoiCells, ContainersGiveTheCellsCutAlone) {
  expect_containers_give_the_cells_cut_alone(jittered_lattice(6), {43, 44, 79, 80, 86, 129});
}

// Seed pairs a tenth apart across a plane, as at a sampled surface, give flat cells, which most
// of the seeds within twice their farthest vertex miss: the cutter passes over those seeds
// without Voro++, and must cut the cells Voro++'s containers cut with every seed.
TEST(VoronoiCells, FlatCellsAsContainersGiveThem) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  std::vector<Point> positions;
  std::vector<Index> inner;
  for (int i = 0; i < 8; ++i) {
    for (int j = 0; j < 8; ++j) {
      const double x = i + jitter(rng), y = j + jitter(rng);
      for (const double z : {-0.05, 0.05}) {
        if (i >= 2 && i < 6 && j >= 2 && j < 6) inner.push_back(static_cast<Index>(positions.size()));
        positions.emplace_back(x, y, z);
      }
      for (const double z : {-2.0, -1.0, 1.0, 2.0}) positions.emplace_back(i + jitter(rng), j + jitter(rng), z);
    }
  }
  expect_containers_give_the_cells_cut_alone(positions, inner);
}

// A cluster of seeds a thousand times closer than the lattice about it, as where a thin feature
// of the surface sits in a wide box of interior seeds: each container holds the seeds near its
// cell, whatever their spacing, and the cells are those cut alone, in the cluster and around it.
TEST(VoronoiCells, ContainersOnSeedsOfUnevenSpacing) {
  std::vector<Point> positions = jittered_lattice(6);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> in_cluster(-0.01, 0.01);
  const Point centre(2.5, 2.5, 2.5);
  const Index first = static_cast<Index>(positions.size());
  for (int k = 0; k < 400; ++k) positions.push_back(centre + Point(in_cluster(rng), in_cluster(rng), in_cluster(rng)));
  std::vector<Index> inner = {43, 44, 79, 80, 86, 129};
  for (Index k = first; k < first + 400; k += 7) inner.push_back(k);
  expect_containers_give_the_cells_cut_alone(positions, inner);
}

TEST(VoronoiCells, ContainersFlagTheCellsTheyLose) {
  std::vector<Point> positions = jittered_lattice(6);
  positions.push_back(positions[86]);  // a twin: Voro++ cuts each away by the other's plane
  const std::vector<Index> inner = {43, 86, static_cast<Index>(positions.size() - 1)};
  std::vector<char> lost;
  std::vector<cells::RawCell> cells;
  const cells::SeedTree tree(positions);
  ASSERT_NO_THROW(cells = cells::compute_voronoi_cells_in_containers(positions, inner, tree, lost));
  EXPECT_EQ(lost, (std::vector<char>{0, 1, 1}));
  EXPECT_FALSE(cells[0].vertices.empty());
}

}  // namespace
}  // namespace vorocrust
