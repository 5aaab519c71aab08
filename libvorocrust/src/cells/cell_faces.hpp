// cells/cell_faces.hpp — a raw cell's faces over welded points.
//
// welded_faces(cell, first_instance, point_of) maps each face cycle to points, drops a point
// equal to the one before it (a welded edge), and drops faces left with fewer than three points
// (welded faces). Both cells beside a face see the same points, so they drop the same edges and
// faces. Returns nullopt when a face visits a point twice, or when the cell is not closed (an edge
// not used exactly once in each direction): welding went wrong for that cell.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "cells/voronoi_cells.hpp"

namespace vorocrust::cells {

struct CellFaces {
  std::vector<std::int32_t> neighbours;  // per face: the seed across it
  std::vector<std::uint32_t> starts;     // per face: where its polygon starts in `points`; plus the end
  std::vector<Index> points;             // counter-clockwise seen from outside
  std::size_t num_faces() const { return neighbours.size(); }
};

std::optional<CellFaces> welded_faces(const RawCell& cell, std::size_t first_instance, const std::vector<Index>& point_of);

// Drops, from every face of `cells`, the points that are in exactly two faces of every cell that
// has them: a convex cell's vertex is in three faces at least, so such a point only splits an
// edge. Round-off leaves them at degenerate edges, where four seeds lie on one circle (VoroCrust
// puts its seeds where spheres meet, so the two pairs of one ball pair share a circle): a plane
// that touches a cell along such an edge splits it, and the neighbour across the face, cut
// otherwise, does not. Faces left with fewer than three points go too. Returns how many points
// were dropped (`num_points`: the welded points).
std::size_t drop_edge_points(std::vector<CellFaces>& cells, std::size_t num_points);

}  // namespace vorocrust::cells
