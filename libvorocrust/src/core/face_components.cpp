#include "core/face_components.hpp"

namespace vorocrust {

FaceComponents face_components(const SurfaceMesh& mesh, const EdgeTopology& topology) {
  FaceComponents result;
  std::size_t count = 0;
  result.of_face = label_face_components(mesh, topology, [](std::size_t) { return true; }, count);
  std::vector<ComponentInfo>& parts = result.components;
  parts.resize(count);
  result.faces.resize(count);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) result.faces[result.of_face[f]].push_back(static_cast<Index>(f));
  // Every face of an edge lies in one component, since the edge joins them all.
  for (std::size_t e = 0; e < topology.num_edges(); ++e) {
    ComponentInfo& c = parts[result.of_face[topology.faces_of(e)[0]]];
    ++c.edges;
    c.boundary_edges += topology.is_boundary(e);
    c.non_manifold_edges += topology.is_non_manifold(e);
  }
  // A vertex may be shared by components that meet only there; it counts in each.
  std::vector<Index> stamp(mesh.vertices.size(), ~Index{0});
  for (Index c = 0; c < count; ++c) {
    parts[c].faces = result.faces[c].size();
    for (Index f : result.faces[c]) {
      for (Index v : mesh.triangles[f]) {
        if (stamp[v] != c) stamp[v] = c, ++parts[c].vertices;
      }
    }
  }
  return result;
}

}  // namespace vorocrust
