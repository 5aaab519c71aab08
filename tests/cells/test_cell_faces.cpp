// drop_edge_points: a point that only splits an edge of every cell that has it leaves every face,
// so that the two sides of a face agree; a point some cell has as a corner stays; a face left
// without an area goes.
#include <gtest/gtest.h>

#include <vector>

#include "cells/cell_faces.hpp"

namespace vorocrust::cells {
namespace {

CellFaces cell_of(const std::vector<std::vector<Index>>& faces) {
  CellFaces c;
  for (const auto& f : faces) {
    c.neighbours.push_back(static_cast<std::int32_t>(c.neighbours.size()));
    c.starts.push_back(static_cast<std::uint32_t>(c.points.size()));
    c.points.insert(c.points.end(), f.begin(), f.end());
  }
  c.starts.push_back(static_cast<std::uint32_t>(c.points.size()));
  return c;
}

std::vector<Index> face(const CellFaces& c, std::size_t f) {
  return {c.points.begin() + c.starts[f], c.points.begin() + c.starts[f + 1]};
}

// The unit cube, its points 0-7, with point 8 splitting its edge from 0 to 1 (in the bottom and
// the front face); and the cube below it, which shares the bottom face without point 8.
std::vector<CellFaces> two_cubes() {
  const CellFaces upper = cell_of({{0, 3, 2, 1, 8}, {4, 5, 6, 7}, {0, 8, 1, 5, 4}, {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}});
  const CellFaces lower = cell_of({{9, 10, 11, 12}, {0, 1, 2, 3}, {9, 12, 1, 0}, {10, 3, 2, 11}, {9, 0, 3, 10}, {12, 11, 2, 1}});
  return {upper, lower};
}

TEST(DropEdgePoints, APointThatOnlySplitsAnEdgeLeavesTheFacesThatHaveIt) {
  std::vector<CellFaces> cells = two_cubes();
  EXPECT_EQ(drop_edge_points(cells, 13), 1u);
  EXPECT_EQ(face(cells[0], 0), (std::vector<Index>{0, 3, 2, 1}));  // now the lower cube's top, reversed
  EXPECT_EQ(face(cells[0], 2), (std::vector<Index>{0, 1, 5, 4}));
  EXPECT_EQ(face(cells[0], 1), (std::vector<Index>{4, 5, 6, 7}));
  EXPECT_EQ(cells[0].starts.back(), 24u);
  EXPECT_EQ(cells[1].points.size(), 24u);  // untouched
}

TEST(DropEdgePoints, APointThatIsACornerOfSomeCellStays) {
  std::vector<CellFaces> cells = two_cubes();
  cells.push_back(cell_of({{8, 20, 21}, {8, 21, 22}, {8, 22, 20}, {20, 22, 21}}));
  EXPECT_EQ(drop_edge_points(cells, 23), 0u);
  EXPECT_EQ(face(cells[0], 0), (std::vector<Index>{0, 3, 2, 1, 8}));
}

// A sliver triangle along the cube's edge from 0 to 1, its corner 8 on that edge: with 8 gone it
// spans no area, and the cell keeps its six faces (a face left with two points failed the quality
// stage's check on cgal_bones).
TEST(DropEdgePoints, AFaceLeftWithTwoPointsGoes) {
  std::vector<CellFaces> cells{
      cell_of({{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 8, 1, 5, 4}, {0, 1, 8}, {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}})};
  EXPECT_EQ(drop_edge_points(cells, 9), 1u);
  ASSERT_EQ(cells[0].num_faces(), 6u);
  EXPECT_EQ(cells[0].neighbours, (std::vector<std::int32_t>{0, 1, 2, 4, 5, 6}));
  EXPECT_EQ(face(cells[0], 2), (std::vector<Index>{0, 1, 5, 4}));
  EXPECT_EQ(face(cells[0], 3), (std::vector<Index>{3, 7, 6, 2}));
  EXPECT_EQ(cells[0].starts.size(), 7u);
  EXPECT_EQ(cells[0].starts.back(), 24u);
}

TEST(DropEdgePoints, NothingToDropChangesNothing) {
  std::vector<CellFaces> cells = two_cubes();
  cells[0] = cell_of({{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}});
  const std::vector<CellFaces> before = cells;
  EXPECT_EQ(drop_edge_points(cells, 13), 0u);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    EXPECT_EQ(cells[c].points, before[c].points);
    EXPECT_EQ(cells[c].starts, before[c].starts);
  }
}

}  // namespace
}  // namespace vorocrust::cells
