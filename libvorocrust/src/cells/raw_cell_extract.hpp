// Internal: a Voro++ cell as a RawCell, numbered by position so that equal cells are equal
// whatever the order of the cuts that made them (voronoi_cells.hpp says why). Shared by the two
// ways cells are cut: one at a time (cell_cutter.cpp) and in Voro++'s containers (local_containers.cpp).
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

// The Voro++ cell of the seed at p, computed `scale` times as small, as a RawCell in canonical
// numbering.
void extract(voro::voronoicell_neighbor& voro_cell, const Point& p, RawCell& cell, Scratch& scratch, double scale = 1);

}  // namespace vorocrust::cells
