// Internal: a Voro++ cell as a RawCell, numbered by position so that equal cells are equal
// whatever the order of the cuts that made them (voronoi_cells.hpp says why). Shared by the two
// ways cells are cut: one at a time (cell_cutter.cpp) and in Voro++'s containers (local_containers.cpp,
// the tests' reference).
#pragma once

#include <cstdint>
#include <vector>
#include <voro++.hh>

#include "cells/voronoi_cells.hpp"

namespace vorocrust::cells {

// Buffers a cutter reuses from cell to cell.
struct Scratch {
  std::vector<double> xyz;
  std::vector<int> faces, ids;
  std::vector<std::uint32_t> near;
  std::vector<double> distance2;
  std::vector<std::uint32_t> order, rank, faces_order;
};

// Whether every edge of a Voro++ cell is listed at both its ends, each end pointing back to the
// other. Among nearly cospherical seeds cut in an unlucky order, Voro++ 0.4.6 can leave a cell two
// of whose vertices share one edge table (igl_camelhead: the cell of seed 66890 in a container of
// 134 seeds, beside a vertex of order 4), and its own walk round the faces then reads unmapped
// memory.
bool edges_consistent(const voro::voronoicell_base& cell);

// The Voro++ cell of the seed at p, computed `scale` times as small, as a RawCell in canonical
// numbering; false, leaving `cell` as it was, when Voro++'s cell is not whole (edges_consistent).
[[nodiscard]] bool extract(voro::voronoicell_neighbor& voro_cell, const Point& p, RawCell& cell, Scratch& scratch,
                           double scale = 1);

}  // namespace vorocrust::cells
