// vorocrust/cell_quality.hpp — how well shaped the cells of a Voronoi mesh are: the volume
// quality of the paper's section 3.
//
// Per cell:
// - aspect ratio = R / r, the paper's definition (its footnote 3): R the radius of the smallest
//   sphere enclosing the cell (Welzl's algorithm over the cell's points), r the radius of the
//   largest ball inside it (a linear program over the cell's face planes, solved by Seidel's
//   algorithm). sqrt(3) for a cube, sqrt(2) for the rhombic dodecahedron of the FCC lattice,
//   sqrt(5/3) for the truncated octahedron of the BCC lattice; 1 only for a ball. A cell without
//   interior (r = 0) has aspect ratio infinity.
// - volume and face count, as the mesh gives them;
// - shortest edge relative to the cell's size: the shortest edge of its faces divided by the
//   cube root of its volume, 1 for a cube, so a short edge reads the same in a large cell and a
//   small one.
// Per cell part, over all cells (the short edges and tiny faces the paper names as its main
// limitation): each edge's length over the cell's size (the cube root of its volume), each face's
// area over the size squared, and the dihedral angle inside the cell at each edge, between the
// two faces meeting there (180 degrees minus the angle between their outward normals; an edge of
// a face without area has none). A part is counted once for each cell it bounds, against that
// cell's size, so an edge of three cells counts three times. The figures are split between the
// boundary layer and the interior. The boundary layer is the cells of the seeds the surface stage
// and the cells' repairs placed (VoronoiCell::seed_kind surface and cap: on protecting spheres;
// repair: splitting the cells beside them), none free to move, and any other cell with a face on
// the surface (to no cell, or to a cell of another material); the interior is the cells of the
// seeds the interior sampler placed.
// Per face with a cell on each side: the angle between its normal and the link between the two
// seeds (face_orthogonality.hpp; 0 for Voronoi cells up to rounding) and, as OpenFOAM's checkMesh
// measures them, the angle to the link between the cells' centroids (its "non-orthogonality")
// and skewness (face_skewness.hpp).
// The sphere and the ball are computed in a frame where the cell has unit size, so their
// tolerances are relative; the enclosing sphere is grown to its farthest point and the ball
// shrunk to its nearest face plane, so the sphere always encloses and the ball always fits: the
// aspect ratio errs, if at all, by rounding on the large side. Each cell is measured alone, in
// parallel; the figures do not depend on the thread count (sums run in cell order).
//
// Throws Error(InvalidGeometry) for a mesh without cells and for a cell without faces or with a
// point index outside the mesh, Error(Usage) for options out of range.
#pragma once

#include "vorocrust/api.hpp"

#include <cstddef>
#include <array>
#include <cstdint>
#include <vector>

#include "vorocrust/cells.hpp"

namespace vorocrust {

struct VOROCRUST_API CellQualityOptions {
  // The aspect-ratio histogram: `histogram_bins` bins evenly over [1, histogram_high], bin k
  // holding [1 + k w, 1 + (k + 1) w) with w = (histogram_high - 1) / bins, the last bin also
  // histogram_high itself, the first bin anything below 1 (rounding); ratios above
  // histogram_high are counted apart (CellQuality::aspect_ratio_above_high). The default cap is
  // the paper's bound for the bunny (4.86, issue target 5), so that count is the cells over it.
  std::size_t histogram_bins = 16;
  double histogram_high = 5;
  int threads = 0;  // 0 = all hardware threads

  // Throws Error(Usage) naming the first option out of its range.
  void check() const;
};

struct VOROCRUST_API CellShape {
  double circumradius = 0;  // R: of the smallest sphere enclosing the cell
  Point circumcentre = Point::Zero();
  double inradius = 0;  // r: of the largest ball inside the cell
  Point incentre = Point::Zero();
  double aspect_ratio = 0;  // R / r
  double volume = 0;        // VoronoiCell::volume
  std::size_t faces = 0;
  double shortest_edge = 0;           // in the mesh's units
  double shortest_edge_relative = 0;  // shortest_edge / cbrt(volume); 0 without volume
};

// How one measure of many cell parts is spread.
struct VOROCRUST_API PartDistribution {
  std::size_t count = 0;
  double min = 0, mean = 0, max = 0;  // 0 when count is 0
  std::size_t min_cell = 0;           // the cell of the smallest (the first of equals)
  // Bins evenly over [low, high] (0 to 2 in 40 bins for lengths and areas, 0 to 180 degrees in 18
  // for angles), values below low in the first; those above high counted apart.
  double low = 0, high = 1;
  std::vector<std::size_t> histogram;
  std::size_t above_high = 0;
  std::vector<double> thresholds;  // ascending
  std::vector<std::size_t> below;  // per threshold, the parts strictly below it
  // 100 below[k] / count; 0 without parts.
  double percent_below(std::size_t k) const;
};

struct VOROCRUST_API LayerParts {
  const char* name = "";  // "boundary layer" or "interior"
  std::size_t cells = 0;
  PartDistribution edge_length;     // edge / cbrt(volume); thresholds 0.01, 0.05, 0.1
  PartDistribution face_area;       // area / cbrt(volume)^2; thresholds 1e-4, 1e-3, 0.01
  PartDistribution dihedral_angle;  // degrees; thresholds 10, 20
};

struct VOROCRUST_API CellQuality {
  std::vector<CellShape> cells;  // one per VoronoiMesh::cells, in its order

  double min_aspect_ratio = 0, mean_aspect_ratio = 0, max_aspect_ratio = 0;
  std::size_t worst_cell = 0;  // the cell of the largest aspect ratio (the first of equals)
  Index worst_seed = 0;        // its seed
  double histogram_low = 1, histogram_high = 5;
  std::vector<std::size_t> aspect_ratio_histogram;  // see CellQualityOptions
  std::size_t aspect_ratio_above_high = 0;

  double min_volume = 0, max_volume = 0, total_volume = 0;
  std::size_t min_faces = 0, max_faces = 0;
  double mean_faces = 0;
  double min_shortest_edge_relative = 0, mean_shortest_edge_relative = 0;
  std::size_t shortest_edge_cell = 0;  // the cell of the smallest relative edge (the first of equals)

  LayerParts boundary_layer{.name = "boundary layer"}, interior{.name = "interior"};  // see the top of this header
  // Both, the boundary layer first, for the tables and pictures that list them.
  std::array<const LayerParts*, 2> layers() const { return {&boundary_layer, &interior}; }

  // Face skewness as checkMesh measures it (face_skewness.hpp): the largest, its face, and the
  // faces above checkMesh's threshold of 4, which fail its check.
  double max_skewness = 0;
  std::size_t most_skew_face = 0;
  std::size_t highly_skew_faces = 0;

  // Degrees, over the faces with a cell on each side (face_orthogonality.hpp): the largest angle
  // between a face and its seeds' link, and its face; checkMesh's non-orthogonality, largest and
  // mean (as checkMesh averages: the angle whose cosine is the faces' mean cosine).
  double max_link_angle = 0;
  std::size_t link_angle_face = 0;
  double max_non_orthogonality = 0, mean_non_orthogonality = 0;
};

VOROCRUST_API CellQuality measure_cell_quality(const VoronoiMesh& mesh, const CellQualityOptions& options = {});

}  // namespace vorocrust
