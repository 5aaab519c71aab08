// cells/weld_vertices.hpp — one point per Voronoi vertex, whichever cells have it.
//
// weld_vertices(cells, cell_seeds, cell_of_seed, frame, relative) numbers the vertices of every
// raw cell as instances, cell after cell, and makes instances closer than their tolerance one
// point. The tolerance of an instance of cell c is relative[c] * max(R, 1) in the frame's units
// (seed spacing), R being its distance to its cell's seed, the radius of its empty sphere; two
// instances are one point within the larger of their tolerances. compute_cells starts every cell
// with 1e-9, far above Voro++'s 1e-11 and far below any edge that is not an artefact of a
// degenerate vertex, and raises it only for cells that still disagree with a neighbour, and those
// neighbours: welded at 1e-6, a tiny cell's face turns by degrees. Counterparts on the two sides
// of a face shared by two cells are united first, then all remaining points within tolerance of
// each other, by a sweep in x; the unions are transitive, so every cell sees one point for a
// cluster.
// Points are numbered in the order of their first instance.
//
// A point is placed at the circumcentre of the seeds around one of its instances (its cell's
// seed and the seeds across the faces at it), computed from the original seed coordinates, so
// that it is equidistant from them up to round-off; when those seeds are too nearly coplanar for
// that (the circumcentre strays by more than ten tolerances from the instance) it stays at the
// instance. Points so placed within tolerance of each other are one point too.
#pragma once

#include <cstdint>
#include <vector>

#include "cells/voronoi_cells.hpp"

namespace vorocrust::cells {

// The normalized frame in which cells are computed: normalized = (original - centre) / scale.
struct Frame {
  Point centre = Point::Zero();
  double scale = 1;
  std::vector<Point> original;    // seed positions as given
  std::vector<Point> normalized;  // the same in the frame
};

struct WeldedVertices {
  std::vector<std::size_t> first_instance;  // per cell, then the total: cell c's vertex v is
                                            // instance first_instance[c] + v
  std::vector<Index> point_of;              // per instance
  std::vector<Point> points;                // original coordinates
};

// Vertices of a cell (in the frame) this near each other become one point: `relative` times the
// radius of the vertex's empty sphere, or of a unit one when that is smaller.
double weld_tolerance(const Point& vertex, const Point& seed, double relative);

WeldedVertices weld_vertices(const std::vector<RawCell>& cells, const std::vector<Index>& cell_seeds,
                             const std::vector<std::int32_t>& cell_of_seed, const Frame& frame,
                             const std::vector<double>& relative_tolerance);

}  // namespace vorocrust::cells
