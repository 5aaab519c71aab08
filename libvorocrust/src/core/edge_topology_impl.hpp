// Template definitions for edge_topology.hpp.
#pragma once

#include <numeric>

namespace vorocrust {

template <class JoinPredicate>
std::vector<Index> label_face_components(const SurfaceMesh& mesh, const EdgeTopology& topology,
                                         JoinPredicate joins, std::size_t& count) {
  const std::size_t n = mesh.triangles.size();
  std::vector<Index> parent(n);
  std::iota(parent.begin(), parent.end(), Index{0});
  const auto find = [&](Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (std::size_t e = 0; e < topology.num_edges(); ++e) {
    if (topology.valence(e) < 2 || !joins(e)) continue;
    const auto faces = topology.faces_of(e);
    for (std::size_t k = 1; k < faces.size(); ++k) {
      const Index a = find(faces[0]), b = find(faces[k]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  }
  std::vector<Index> label(n);
  count = 0;
  for (std::size_t f = 0; f < n; ++f) {
    const Index root = find(static_cast<Index>(f));
    label[f] = root == f ? static_cast<Index>(count++) : label[root];
  }
  return label;
}

}  // namespace vorocrust
