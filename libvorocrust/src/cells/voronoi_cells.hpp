// cells/voronoi_cells.hpp — the raw Voronoi cells of chosen seeds, computed with Voro++.
//
// compute_voronoi_cells(positions, cell_seeds) returns, for each seed in `cell_seeds`
// (in that order), its Voronoi cell among all `positions`, as Voro++ computes it: vertices
// (absolute, in the frame of `positions`) and faces (outward cycles of vertex indices, each with
// the seed across it). Degenerate vertices come as Voro++ resolves them, so two cells may
// disagree on them by round-off or by a tiny edge: welding is the caller's job.
//
// The work is split into slabs of the seeds' bounding box along its longest axis, a fixed number
// of seeds each, computed in parallel, one Voro++ container per slab holding the slab's seeds
// and a margin of neighbouring seeds. A cell is kept only when the empty sphere of each of its
// vertices lies inside the container's range along the axis (so no seed left out could cut it);
// otherwise it is computed again with a wider margin. The slabs do not depend on the thread
// count, nor does the result.
//
// `positions` should be scaled so that seeds are about one unit apart: Voro++ decides
// degeneracies with an absolute tolerance of 1e-11.
//
// Throws Error(InvalidGeometry) "cell of seed N is not bounded by seeds" when a cell reaches the
// container's outer walls (the bounding box of all seeds, grown by one unit).
#pragma once

#include <cstdint>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::cells {

struct RawCell {
  std::vector<Point> vertices;
  std::vector<std::int32_t> neighbours;  // per face: the seed across it, or a Voro++ wall (< 0)
  std::vector<std::uint32_t> starts;     // per face: where its cycle starts in `cycles`; plus the end
  std::vector<std::uint32_t> cycles;     // vertex indices, counter-clockwise seen from outside
  std::size_t num_faces() const { return neighbours.size(); }
};

std::vector<RawCell> compute_voronoi_cells(const std::vector<Point>& positions, const std::vector<Index>& cell_seeds);

// Computes cells[k] again for each k in `which`, each alone: the planes of the other seeds cut it
// nearest first, with no container. Voro++'s containers cut in the order of their grid blocks,
// and where many seeds are nearly cospherical (the rule at VoroCrust's surface seeds) that order
// can, rarely, leave a cell that misses a neighbour; cutting nearest first does not, and is used
// on the cells the assembly finds at odds with their neighbours. A cell that reaches the initial
// box (bigger than all seeds) keeps a wall face (< 0) as a neighbour.
void recompute_nearest_first(const std::vector<Point>& positions, const std::vector<Index>& cell_seeds,
                             const std::vector<std::size_t>& which, std::vector<RawCell>& cells);

}  // namespace vorocrust::cells
