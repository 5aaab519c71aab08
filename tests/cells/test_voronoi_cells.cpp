// The cells in Voro++'s containers, the assembly's first fallback: the same cells as cut alone,
// and a cell Voro++ cuts away to nothing flagged as lost, for the caller to keep the cell it had,
// rather than ending the run.
#include <gtest/gtest.h>

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

TEST(VoronoiCells, ContainersGiveTheCellsCutAlone) {
  const std::vector<Point> positions = jittered_lattice(6);
  const std::vector<Index> inner = {43, 44, 79, 80, 86, 129};
  std::vector<char> lost;
  const std::vector<cells::RawCell> in_containers = cells::compute_voronoi_cells_in_containers(positions, inner, lost);
  const std::vector<cells::RawCell> alone = cells::compute_voronoi_cells(positions, inner);
  ASSERT_EQ(lost, std::vector<char>(inner.size(), 0));
  for (std::size_t k = 0; k < inner.size(); ++k) {
    EXPECT_EQ(in_containers[k].neighbours, alone[k].neighbours) << "seed " << inner[k];
    ASSERT_EQ(in_containers[k].vertices.size(), alone[k].vertices.size()) << "seed " << inner[k];
    for (std::size_t v = 0; v < alone[k].vertices.size(); ++v) {
      EXPECT_LT((in_containers[k].vertices[v] - alone[k].vertices[v]).norm(), 1e-12) << "seed " << inner[k];
    }
  }
}

TEST(VoronoiCells, ContainersFlagTheCellsTheyLose) {
  std::vector<Point> positions = jittered_lattice(6);
  positions.push_back(positions[86]);  // a twin: Voro++ cuts each away by the other's plane
  const std::vector<Index> inner = {43, 86, static_cast<Index>(positions.size() - 1)};
  std::vector<char> lost;
  std::vector<cells::RawCell> cells;
  ASSERT_NO_THROW(cells = cells::compute_voronoi_cells_in_containers(positions, inner, lost));
  EXPECT_EQ(lost, (std::vector<char>{0, 1, 1}));
  EXPECT_FALSE(cells[0].vertices.empty());
}

}  // namespace
}  // namespace vorocrust
