// Internal: the faces around an edge in the order a turn about the edge meets them.
//
// Around an edge shared by k faces, space is cut into k wedges, each between two faces that are
// consecutive in angle; the two face sides bounding a wedge face the same region of space. The
// order is decided with exact orientation predicates, so nearly coplanar faces (a wall meeting
// a box side at a right angle, two sheets meeting almost flat) are ordered as they truly are.
#pragma once

#include <span>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::regions {

// `faces` (each holding edge {a, b}) sorted by their angle counter-clockwise about the direction
// a -> b, starting from the first of them. Faces lying on one half-plane (overlapping faces,
// which validation rejects) keep their input order.
std::vector<Index> faces_around_edge(const SurfaceMesh& mesh, Index a, Index b, std::span<const Index> faces);

}  // namespace vorocrust::regions
