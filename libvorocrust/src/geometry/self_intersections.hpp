// Internal: the faces of a mesh that intersect each other improperly.
//
// Contract: returns every pair (i, j), i < j, of faces that meet anywhere other than the vertex
// or edge they share by index (see triangle_intersection.hpp for the exact semantics; touching
// counts). The list is sorted and the same on every run, whatever the number of threads.
// Never reported here, because other checks report them: degenerate (zero-area) faces, faces
// with a vertex index out of range, and pairs of faces on the same three vertices (duplicates).
// Cost: a bounding-volume hierarchy limits exact tests to faces whose boxes overlap, so it is
// near O(n log n) for surfaces without huge clusters of overlapping faces.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::geometry {

using FacePair = std::pair<std::size_t, std::size_t>;

std::vector<FacePair> find_self_intersections(const SurfaceMesh& mesh);

}  // namespace vorocrust::geometry
