// Internal: short edges welded (Ebeida and Mitchell 2011, section 2.4): the two points of every
// edge shorter than `fraction` of the local spacing become one, so that the shortest edge, and
// with it an explicit simulation's time step, is bounded from below.
//
// Contract of weld_short_edges(mesh, spacing, fraction):
// - `spacing[c]` is cell c's local spacing (a clipped mesh's seed radius); an edge is short when
//   it is shorter than `fraction` times the least spacing of the cells whose faces have it.
//   Points joined by short edges, directly or in a chain, become one point, at the mean of those
//   of them on the boundary (faces toward no cell) where any is, else of all of them: a welded
//   point stays on the boundary when its chain touches it.
// - Each face keeps its other points in order; a face left with fewer than three is dropped from
//   both its cells. A chain that would leave a face with one point twice (a pinch), or a cell with
//   fewer than four faces, is not welded (stats.kept_edges counts its short edges).
// - Cells stay closed: an edge that vanishes does so in both faces of each cell that had it. Faces
//   whose points moved are no longer planar in general: stats.max_non_planarity is the largest
//   distance of a face's point from the face's plane (through its points' mean, normal by
//   Newell's rule), over the face's diameter. Volumes and centroids are measured again.
#pragma once

#include <vector>

#include "vorocrust/cells.hpp"
#include "vorocrust/stats.hpp"

namespace vorocrust::cells {

WeldStats weld_short_edges(VoronoiMesh& mesh, const std::vector<double>& spacing, double fraction);

}  // namespace vorocrust::cells
