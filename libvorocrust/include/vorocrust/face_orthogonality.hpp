// vorocrust/face_orthogonality.hpp — how far the faces of a Voronoi mesh turn from the links
// between the cells they separate, in degrees, for a face with a cell on each side (0 for any
// other face, as checkMesh leaves boundary faces out too).
//
// - link_angle: between the face's normal and the link between the two cells' seeds
//   (VoronoiCell::site). A Voronoi face is orthogonal to that link, so this measures only how far
//   rounding and welding (cells.hpp) moved the face's points; a finite-volume code that puts its
//   values at the seeds, as TOUGH and PFLOTRAN do, sees this angle.
// - centroid_non_orthogonality: between the face's normal and the link between the two cells'
//   centroids, which is what OpenFOAM's checkMesh reports as "non-orthogonality". Voronoi cells
//   near the surface have centroids well away from their seeds, so this is not 0.
#pragma once

#include "vorocrust/api.hpp"

#include <cstddef>

#include "vorocrust/cells.hpp"

namespace vorocrust {

VOROCRUST_API double link_angle(const VoronoiMesh& mesh, std::size_t face);
VOROCRUST_API double centroid_non_orthogonality(const VoronoiMesh& mesh, std::size_t face);

}  // namespace vorocrust
