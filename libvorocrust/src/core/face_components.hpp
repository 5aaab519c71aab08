// Internal: the connected components of a triangle soup and what each one holds.
//
// Faces are joined through every shared edge (an edge with three faces joins all three), and
// components are numbered in order of their smallest face, so the numbering depends on the
// mesh alone. Each component counts its faces, the vertices and edges those faces use, and its
// boundary (one face) and non-manifold (three or more faces) edges; area, genus and volume are
// left to the callers that want them.
#pragma once

#include <vector>

#include "core/edge_topology.hpp"
#include "vorocrust/mesh_info.hpp"

namespace vorocrust {

struct FaceComponents {
  std::vector<Index> of_face;                // the component of each face
  std::vector<std::vector<Index>> faces;     // the faces of each component, ascending
  std::vector<ComponentInfo> components;     // counts only
};

FaceComponents face_components(const SurfaceMesh& mesh, const EdgeTopology& topology);

}  // namespace vorocrust
