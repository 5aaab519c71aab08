// Voro++ by itself, as the cells benchmarks measure it against compute_cells: one container of
// every seed in [lo, hi] on one thread, the material cells (region > 0) computed in the order
// they were put, each with its neighbours, and its vertices, faces and neighbour ids extracted.
// Returns how many cells Voro++ gave (it may lose some among nearly coincident seeds).
#pragma once

#include <array>
#include <cstddef>
#include <vector>
#include <voro++.hh>

#include "vorocrust/seeds.hpp"

namespace vorocrust::bench {

inline std::size_t voropp_full_cells(const std::vector<Seed>& seeds, const Point& lo, const Point& hi,
                                     const std::array<int, 3>& blocks) {
  voro::container con(lo.x(), hi.x(), lo.y(), hi.y(), lo.z(), hi.z(), blocks[0], blocks[1], blocks[2], false, false,
                      false, 8);
  voro::particle_order order;
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    const Point& p = seeds[s].position;
    if (seeds[s].region > 0) con.put(order, static_cast<int>(s), p.x(), p.y(), p.z());
    else con.put(static_cast<int>(s), p.x(), p.y(), p.z());
  }
  voro::c_loop_order loop(con, order);
  voro::voronoicell_neighbor cell;
  std::vector<double> xyz;
  std::vector<int> faces, ids;
  std::size_t cells = 0;
  if (loop.start()) {
    do {
      if (!con.compute_cell(cell, loop)) continue;
      double x, y, z;
      loop.pos(x, y, z);
      cell.vertices(x, y, z, xyz);
      cell.face_vertices(faces);
      cell.neighbors(ids);
      ++cells;
    } while (loop.inc());
  }
  return cells;
}

}  // namespace vorocrust::bench
