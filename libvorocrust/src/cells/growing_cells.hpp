// cells/growing_cells.hpp — the cells of a seed set that grows at its end, cut again only where
// the new seeds reach.
//
// GrowingCells(seeds, options) cuts the cell of every material seed (options.materials) and
// checks the seeds as compute_cells does. add_seeds(seeds), given the seeds it has followed by
// new ones, cuts the new seeds' cells and, of the others, only those whose reach (RawCell::reach2:
// the farthest seed their cut met) a new seed enters: no other cut would change, even by
// round-off. mesh() welds and assembles the cells as they stand. The skew repair adds a few dozen
// seeds to tens of thousands, so it pays for the new seeds' neighbourhoods, not for all the cells
// again; and it finds its skew faces on the cells as cut (skew_faces()), since welding and
// assembling every cell, which only a mesh needs, costs several times what cutting a few does.
//
// mesh() is compute_cells(seeds, options) for the seeds as they stand, bit for bit: cells are
// cut in a frame that a few seeds more do not change (a power-of-two scale about the box of the
// seeds; when either changes, add_seeds cuts every cell again) and in an order that does not
// depend on the seeds' k-d tree (voronoi_cells.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "cells/voronoi_cells.hpp"
#include "cells/weld_vertices.hpp"
#include "vorocrust/cells.hpp"

namespace vorocrust::cells {

// A face of the cells as cut, before welding: the faces of mesh() but for points welded within
// round-off, which move its measures by as little.
struct CutFace {
  Index owner_seed = 0;               // the lower cell's seed
  std::int32_t neighbour_seed = -1;   // the seed across, or a Voro++ wall (< 0)
  bool between_cells = false;         // whether the seed across has a cell
  FaceGeometry geometry;              // normal from the owner's side
  double skewness = 0;                // as face_skewness measures it, with the cells' centroids as cut
  Point owner_centroid = Point::Zero();
  Point neighbour_centroid = Point::Zero();  // where there is a cell across
};

// A cell whose aspect ratio exceeds a bound: its seed and its centroid.
struct LongCell {
  Index seed = 0;
  Point centroid = Point::Zero();
  Point tip = Point::Zero();  // the cell's vertex farthest from its seed
};

class GrowingCells {
 public:
  GrowingCells(const std::vector<Seed>& seeds, const CellsOptions& options);
  void add_seeds(const std::vector<Seed>& seeds);
  // The cells welded and assembled. On a GrowingCells about to go (an rvalue), its cells as cut
  // move into the assembly instead of being copied: the object is spent after.
  VoronoiMesh mesh() const&;
  VoronoiMesh mesh() &&;
  // The faces whose skewness exceeds `threshold`, each once, in the order of their lower cell.
  // Measured again only for the cells cut since the last call and their neighbours (a face's
  // skewness needs both centroids); the same faces as measuring every cell.
  std::vector<CutFace> skew_faces(double threshold);
  // The cells whose aspect ratio exceeds `bound`, as cell_quality measures it but on the cells as
  // cut, in the order of their cells. Measured again only for the cells cut since the last call:
  // the split of cells too long needs no welded mesh, which costs far more to make than this.
  std::vector<LongCell> long_cells(double bound);

 private:
  // The mesh of the cells `cell(c)` gives for cell c, a copy of raw_[c] or raw_[c] itself.
  template <class Cell>
  VoronoiMesh assemble(Cell&& cell) const;
  void add_cell(std::size_t seed);
  void cut_all();
  template <class Work>
  void in_arena(Work&& work) const;  // on options_.threads threads

  std::vector<Seed> seeds_;
  CellsOptions options_;
  Frame frame_;
  std::vector<Index> cell_seeds_;
  std::vector<std::int32_t> cell_of_seed_;  // per seed: its cell, or kNoCell
  std::vector<RawCell> raw_;                // per cell, as cut (mesh() cuts its fallbacks apart)
  // skew_faces' figures per cell, kept between calls: its centroid, the skew faces it owns, and
  // whether it was cut since they were measured (at skew_threshold_).
  std::vector<Point> centroid_;
  std::vector<std::vector<CutFace>> owned_skew_;
  std::vector<char> cut_since_;
  // long_cells' figures per cell, kept between calls: its aspect ratio (or a bound on it within
  // ratio_bound_), and whether it was cut since that was measured.
  std::vector<double> aspect_ratio_;
  std::vector<char> ratio_stale_;
  double ratio_bound_ = 0;
  double skew_threshold_ = 0;
};

}  // namespace vorocrust::cells
