// cells/voronoi_cells.hpp — the raw Voronoi cells of chosen seeds, computed with Voro++.
//
// compute_voronoi_cells(positions, cell_seeds) returns, for each seed in `cell_seeds`
// (in that order), its Voronoi cell among all `positions`: vertices (absolute, in the frame of
// `positions`) and faces (outward cycles of vertex indices, each with the seed across it).
// Degenerate vertices come as Voro++ resolves them, so two cells may disagree on them by
// round-off or by a tiny edge: welding is the caller's job.
//
// Each cell is cut alone from a cube bigger than all seeds by the bisector planes of the other
// seeds, nearest first (a k-d tree gives them; ties by seed index), until the next seed is
// farther than twice the cell's farthest vertex. Voro++'s containers were the first choice, but
// their uniform grid suits VoroCrust's seeds badly: thin layers of surface seeds, sparse
// interior seeds and outside seeds spread over a box three times the model's crowd some blocks
// and empty others (igl_bunny: 37 s in containers, 9 s nearest first; as fast on even seeds),
// and where many seeds are nearly cospherical their block order could leave a cell missing a
// neighbour. Each cell's cuts depend on its seed and the positions alone, so the result does not
// depend on the thread count or on the order cells are cut in.
//
// `positions` should be scaled so that seeds are about one unit apart: Voro++ decides
// degeneracies with an absolute tolerance of 1e-11.
//
// Throws Error(InvalidGeometry) "cell of seed N is not bounded by seeds" (the lowest such seed)
// when a cell keeps a face of the initial cube.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/point_cloud.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::cells {

struct RawCell {
  std::vector<Point> vertices;
  std::vector<std::int32_t> neighbours;  // per face: the seed across it, or a Voro++ wall (< 0)
  std::vector<std::uint32_t> starts;     // per face: where its cycle starts in `cycles`; plus the end
  std::vector<std::uint32_t> cycles;     // vertex indices, counter-clockwise seen from outside
  // Squared, the distance within which another seed could have changed how the cell was cut
  // (the farthest seed cut, or twice the farthest vertex); set by the cuts alone, not by Voro++'s
  // containers.
  double reach2 = 0;
  // The shortest edge, squared, over the square of the larger of 1 and the radius of its
  // vertices' empty spheres (the unit of welding's tolerances): where Voro++ resolved a
  // degenerate vertex into a tiny edge, it is tiny. 0 until measured: such a cell counts as
  // nearly degenerate.
  double shortest_edge2 = 0;
  std::size_t num_faces() const { return neighbours.size(); }
};

// The k-d tree of the positions that the cuts search, and the bounds of the positions. Building it
// costs as much as cutting thousands of cells: the assembly's fallbacks, which cut a few dozen
// cells again several times, build it once and pass it to each call (`positions` must outlive it
// and stay as they are).
struct SeedTree {
  explicit SeedTree(const std::vector<Point>& positions);
  SeedTree(const SeedTree&) = delete;
  SeedTree& operator=(const SeedTree&) = delete;
  PointCloudAdaptor<Point, IdentityPosition> cloud;
  StaticKdTree<PointCloudAdaptor<Point, IdentityPosition>> tree;
  double half_side = 0;  // of a cube about any seed that holds all seeds
};

std::vector<RawCell> compute_voronoi_cells(const std::vector<Point>& positions, const std::vector<Index>& cell_seeds);

// The same cells from Voro++'s containers, one per cell holding the seeds within its reach
// (widened until every vertex's empty sphere lies within it): Voro++'s own way, against which the
// tests check the cutter. It was the assembly's first fallback for cells at odds with their
// neighbours, until on igl_camelhead Voro++ left cells broken there (raw_cell_extract.hpp) and then
// faulted inside its own cutting (seed 595561): the cutter, nearest seed first, never has. Where
// Voro++ gives no cell (round-off can cut a cell away among seeds that nearly
// coincide: two surface seeds of cgal_bones 4e-5 radii apart) or one that keeps a wall of its
// container, lost[k] is set and cells[k] is not to be used (empty, or the cell with the wall).
// `tree`: the positions' SeedTree.
std::vector<RawCell> compute_voronoi_cells_in_containers(const std::vector<Point>& positions,
                                                         const std::vector<Index>& cell_seeds, const SeedTree& tree,
                                                         std::vector<char>& lost);

// Computes cells[k] again for each k in `which`, from an initial cube 1.375^variant times as
// big. Variant 0 is what compute_voronoi_cells does. Where many seeds are nearly cospherical,
// round-off in the cuts can leave two neighbours disagreeing on a tiny feature; cells cut from
// another cube round otherwise, which is all the assembly needs to try again. With a variant
// above 0 (the assembly's fallbacks) each cell is also checked to hold no vertex nearer another
// seed, and cut from further cubes until it does (a few at most): round-off can make Voro++ lose
// a whole cut, and a fallback must not trade a tiny disagreement for a wedge of another cell.
// `tree`: the positions' SeedTree, or none to build one.
void recompute_voronoi_cells(const std::vector<Point>& positions, const std::vector<Index>& cell_seeds,
                             const std::vector<std::size_t>& which, int variant, std::vector<RawCell>& cells,
                             const SeedTree* tree = nullptr);

// The cells among `which` (indices into `cells`, the cells of `cell_seeds`) with a vertex nearer
// another seed than their own, beyond round-off: cells a lost cut left too big.
std::vector<std::size_t> cells_holding_others(const std::vector<Point>& positions, const std::vector<Index>& cell_seeds,
                                              const std::vector<RawCell>& cells, const std::vector<std::size_t>& which,
                                              const SeedTree* tree = nullptr);

// The cells (indices into `cells`, the cells of `cell_seeds`, cut by compute_voronoi_cells)
// within whose reach2 the seeds `added` lie. The other cells compute_voronoi_cells would cut
// among all the positions exactly as they are.
std::vector<std::size_t> cells_reached(const std::vector<Point>& positions, const std::vector<Index>& cell_seeds,
                                       const std::vector<RawCell>& cells, const std::vector<Index>& added);

}  // namespace vorocrust::cells
