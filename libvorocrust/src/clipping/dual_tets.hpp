// Internal: the tetrahedral mesh dual to a clipped Voronoi mesh (Yan, Wang, Lévy and Liu 2011,
// section 5.2, "final mesh extraction"), and the shape measures of their Table 2.
//
// Contract of dual_tets(clipped):
// - `clipped` is clip_cells' mesh (or any VoronoiMesh whose points are shared by the faces that
//   have them). A point all of whose faces lie between two cells of one material, and which
//   four cells share, is a Voronoi vertex inside that material: its tetrahedron joins the four
//   cells' sites, each site's cell index standing for it, oriented with positive volume. The
//   tetrahedra are the primal Delaunay tetrahedra whose circumcentre lies inside the material.
// - A point of the surface (a face toward no cell or toward another material has it) has no
//   tetrahedron. A point shared by five cells or more (cospherical sites, or welded points) has
//   none either and is counted in `degenerate_points`.
// - Tetrahedra come in the order of their points.
//
// tet_shape(a, b, c, d) measures one tetrahedron as Yan et al. do (after Tournois et al.): the
// smallest and largest dihedral angle in degrees (Q1, Q2), the radius ratio 3 r_in / r_circ (Q3)
// and 12 (9 V^2)^(1/3) / (sum of squared edge lengths) (Q4); Q3 and Q4 are 1 for a regular
// tetrahedron and 0 for a flat one.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "vorocrust/cells.hpp"
#include "vorocrust/stats.hpp"

namespace vorocrust::clipping {

struct DualTets {
  std::vector<std::array<std::uint32_t, 4>> tets;  // cells, standing for their sites
  std::vector<std::int32_t> material;              // per tetrahedron
  std::size_t degenerate_points = 0;
};

DualTets dual_tets(const VoronoiMesh& clipped);

struct TetShape {
  double min_dihedral = 0, max_dihedral = 0;  // degrees
  double radius_ratio = 0;                    // Q3
  double circumradius = 0;
  double q4 = 0;
  double volume = 0;
};

TetShape tet_shape(const Point& a, const Point& b, const Point& c, const Point& d);

// dual_tets(clipped)'s tetrahedra measured: their count, volume and shape figures (means and
// extremes over them; all 0 without a tetrahedron). Summed in order: the same on every run.
DualTetFigures measure_dual_tets(const VoronoiMesh& clipped);

}  // namespace vorocrust::clipping
