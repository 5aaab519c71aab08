// Internal: normal, area and enclosed volume of faces and sets of faces.
#pragma once

#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

// The unit normal of triangle `t` over `vertices` (right-handed), zero for a degenerate one.
Point unit_normal(const std::vector<Point>& vertices, const Triangle& t);
Point face_normal(const SurfaceMesh& mesh, Index face);
double face_area(const SurfaceMesh& mesh, Index face);
Point face_centroid(const SurfaceMesh& mesh, Index face);
double surface_area(const SurfaceMesh& mesh, const std::vector<Index>& faces);

// The diagonal of the bounding box of the vertices the faces use: the unit of the surface
// quality's distances, and of how far smoothing may move the surface.
double bounding_box_diagonal(const SurfaceMesh& mesh);

// Signed volume bounded by `faces` (positive when their normals point outward); meaningful for
// a closed shell. Tetrahedra are taken from the shell's first vertex to keep the sum well
// conditioned far from the origin.
double enclosed_volume(const SurfaceMesh& mesh, const std::vector<Index>& faces);

}  // namespace vorocrust
