// vorocrust/method_figures.hpp — the figures that set meshes of different methods side by side
// (VoroCrust's cells against clipped ones; the paper's section 1 and Figure 1: clipping leaves
// boundary faces with edges far shorter than the faces, and cells that are not convex).
//
// measure_method_figures(mesh, enclosed_volume) gives, for a mesh of any method:
// - per boundary face (a face with no cell across it): its shortest edge over its longest, with
//   a histogram of 20 bins over [0, 1]; and the smallest angle at a corner of such a face;
// - faces per cell (a face counts for each cell it bounds);
// - non-convex cells: a cell with a point beyond the plane of one of its faces, by more than 1e-6
//   of the cell's size (the cube root of its volume);
// - faces between two cells whose normal turns more than 0.05 degrees from their seed link, and
//   the largest such angle (face_orthogonality.hpp);
// - the cells' volume, and its relative difference from `enclosed_volume`.
// Throws Error(InvalidGeometry) for a mesh without cells.
#pragma once

#include "vorocrust/api.hpp"

#include <cstddef>
#include <vector>

#include "vorocrust/cells.hpp"

namespace vorocrust {

struct VOROCRUST_API MethodFigures {
  std::size_t cells = 0, faces = 0, boundary_faces = 0;
  double boundary_edge_ratio_min = 0, boundary_edge_ratio_mean = 0;
  std::size_t boundary_edge_ratio_below_tenth = 0;  // boundary faces whose ratio is below 0.1
  std::vector<std::size_t> boundary_edge_ratio_histogram;
  double boundary_angle_min = 0;  // degrees
  double faces_per_cell = 0;
  std::size_t non_convex_cells = 0;
  std::size_t off_link_faces = 0;  // faces between cells more than 0.05 degrees off their seed link
  double link_angle_max = 0;       // degrees
  double volume = 0;
  double volume_error = 0;  // |volume - enclosed| / enclosed
};

VOROCRUST_API MethodFigures measure_method_figures(const VoronoiMesh& mesh, double enclosed_volume);

}  // namespace vorocrust
