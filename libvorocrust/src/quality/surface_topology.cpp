#include "quality/surface_topology.hpp"

#include <algorithm>
#include <utility>

#include "core/face_components.hpp"

namespace vorocrust {

SurfaceTopology surface_topology(const SurfaceMesh& mesh, const EdgeTopology& topology) {
  const FaceComponents found = face_components(mesh, topology);
  SurfaceTopology result;
  result.components = found.components.size();
  for (const ComponentInfo& c : found.components) {
    result.euler_characteristic.push_back(c.euler_characteristic());
    result.closed.push_back(c.closed());
    result.boundary_edges += c.boundary_edges;
    result.non_manifold_edges += c.non_manifold_edges;
  }
  return result;
}

SurfaceTopology surface_topology(const SurfaceMesh& mesh) { return surface_topology(mesh, build_edge_topology(mesh)); }

bool same_topology(const SurfaceTopology& a, const SurfaceTopology& b) {
  if (a.components != b.components) return false;
  // Components are numbered by face index, which two different meshes need not share: compare
  // them as multisets.
  const auto kinds = [](const SurfaceTopology& t) {
    std::vector<std::pair<long, bool>> k;
    for (std::size_t c = 0; c < t.components; ++c) k.emplace_back(t.euler_characteristic[c], t.closed[c]);
    std::sort(k.begin(), k.end());
    return k;
  };
  return kinds(a) == kinds(b);
}

}  // namespace vorocrust
