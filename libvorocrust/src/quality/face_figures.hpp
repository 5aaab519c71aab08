// Internal: the figures of one face of a Voronoi mesh (face_skewness.hpp,
// face_orthogonality.hpp) from its geometry, for callers that measure all of them and compute
// the geometry once.
#pragma once

#include <cstddef>

#include "vorocrust/cells.hpp"

namespace vorocrust::quality {

// Degrees between a face's unit normal and the link from one point to another; 0 when the link
// or the normal has no direction.
double angle_to_link(const Point& normal, const Point& from, const Point& to);

// checkMesh's skewness of `face`, whose geometry is `g` (face_geometry).
double face_skewness(const VoronoiMesh& mesh, std::size_t face, const FaceGeometry& g);

}  // namespace vorocrust::quality
