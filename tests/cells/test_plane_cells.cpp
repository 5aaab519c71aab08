// Voronoi cells in the plane and their welding (2D domains): degenerate vertices (four seeds
// on one circle, everywhere on a square lattice) become one point shared by every cell.
#include <gtest/gtest.h>

#include "cells/plane_cells.hpp"

namespace vorocrust {
namespace {

TEST(PlaneCells, ASquareLatticeWeldsIntoSquaresSharingTheirCorners) {
  std::vector<Point2> seeds;
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 20; ++j) seeds.emplace_back(0.1 * i + 0.05, 0.1 * j + 0.05);
  }
  const Eigen::AlignedBox2d frame(Point2(-1, -1), Point2(3, 3));
  const auto polygons = cells::plane_voronoi_cells(seeds, frame);
  const cells::PlaneAssembly a = cells::weld_plane_cells(polygons, seeds, {}, {}, 1e-10 * 5.7);
  // Inside cells are unit squares of the lattice: four corners each, area 0.01.
  std::size_t squares = 0;
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    const int col = static_cast<int>(i / 20), row = static_cast<int>(i % 20);
    if (col == 0 || row == 0 || col == 19 || row == 19) continue;
    std::vector<Point2> ring;
    for (Index v : a.polygons[i]) ring.push_back(a.points[v]);
    ASSERT_EQ(ring.size(), 4u) << "cell " << i;
    EXPECT_NEAR(cells::polygon_area(ring), 0.01, 1e-15);
    for (std::int64_t j : a.across[i]) EXPECT_GE(j, 0);
    ++squares;
  }
  EXPECT_EQ(squares, 18u * 18u);
  // Each inner lattice point is one vertex: 19 x 19 inside, plus the frame's.
  std::size_t inner = 0;
  for (const Point2& p : a.points) inner += p.x() > 0.01 && p.x() < 1.99 && p.y() > 0.01 && p.y() < 1.99;
  EXPECT_EQ(inner, 19u * 19u);
}

TEST(PlaneCells, EveryCellHoldsItsSeedAndTheirAreasFillTheFrame) {
  std::vector<Point2> seeds = {{0.3, 0.2}, {0.7, 0.4}, {0.5, 0.9}, {0.1, 0.6}, {0.9, 0.8}};
  const Eigen::AlignedBox2d frame(Point2(0, 0), Point2(1, 1));
  const auto polygons = cells::plane_voronoi_cells(seeds, frame);
  double total = 0;
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    Point2 centroid;
    total += cells::polygon_area(polygons[i].vertices, &centroid);
    // Every vertex is no nearer any other seed than this one.
    for (const Point2& v : polygons[i].vertices) {
      for (const Point2& s : seeds) EXPECT_GE((v - s).norm(), (v - seeds[i]).norm() - 1e-12);
    }
  }
  EXPECT_NEAR(total, 1.0, 1e-14);
}

}  // namespace
}  // namespace vorocrust
