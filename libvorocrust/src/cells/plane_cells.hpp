// Internal: Voronoi cells in the plane, welded into one polygon mesh (2D domains, paper 2.6).
//
// plane_voronoi_cells clips the frame by the bisectors of each seed's nearest seeds, nearest
// first, until no farther seed can reach the cell (twice the cell's reach is less than the
// distance to the next one). Each edge remembers the seed across it, or the frame's side
// (-1 - side).
//
// weld_plane_cells numbers the vertices: a vertex is named by the three seeds (or frame sides)
// it is the circumcentre of, so cells that share it share its number; vertices within
// `tolerance` of a circle's centre become that centre, as the seeds on the circle make it one
// vertex, and edges shorter than `tolerance` collapse, both ends one vertex, in every cell that
// has them (four or more seeds nearly on one circle). Throws Error(InvalidGeometry) when two
// cells then disagree on an edge they share.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "vorocrust/plane.hpp"

namespace vorocrust::cells {

struct PlanePolygon {
  std::vector<Point2> vertices;     // counter-clockwise
  std::vector<std::int64_t> across;  // per edge vertices[k] -> vertices[k + 1]
};

std::vector<PlanePolygon> plane_voronoi_cells(const std::vector<Point2>& seeds, const Eigen::AlignedBox2d& frame);

struct PlaneAssembly {
  std::vector<Point2> points;
  std::vector<std::vector<Index>> polygons;          // per seed
  std::vector<std::vector<std::int64_t>> across;     // per seed, per edge
};

// `on_circles`: per seed, the circles it lies on (-1: none), for the first seeds (the boundary's).
PlaneAssembly weld_plane_cells(const std::vector<PlanePolygon>& cells, const std::vector<Point2>& seeds,
                               const std::vector<PlaneCircle>& circles,
                               const std::vector<std::array<std::int32_t, 2>>& on_circles, double tolerance);

// A polygon's area (positive counter-clockwise) and centroid.
double polygon_area(const std::vector<Point2>& ring, Point2* centroid = nullptr);

}  // namespace vorocrust::cells
