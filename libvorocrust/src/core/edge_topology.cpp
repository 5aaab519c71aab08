#include "core/edge_topology.hpp"

#include <algorithm>

namespace vorocrust {

EdgeTopology build_edge_topology(const SurfaceMesh& mesh) {
  struct Corner {
    Index a, b, face;
    std::uint8_t slot;
  };
  std::vector<Corner> corners;
  corners.reserve(3 * mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    for (std::uint8_t k = 0; k < 3; ++k) {
      const Index u = t[k], v = t[(k + 1) % 3];
      corners.push_back({std::min(u, v), std::max(u, v), static_cast<Index>(f), k});
    }
  }
  std::sort(corners.begin(), corners.end(), [](const Corner& x, const Corner& y) {
    return std::tie(x.a, x.b, x.face, x.slot) < std::tie(y.a, y.b, y.face, y.slot);
  });
  EdgeTopology topo;
  topo.face_edges.resize(mesh.triangles.size());
  topo.edge_faces.reserve(corners.size());
  for (std::size_t i = 0; i < corners.size();) {
    const Index e = static_cast<Index>(topo.edges.size());
    topo.edges.push_back({corners[i].a, corners[i].b});
    topo.face_offsets.push_back(topo.edge_faces.size());
    for (; i < corners.size() && corners[i].a == topo.edges.back()[0] && corners[i].b == topo.edges.back()[1]; ++i) {
      topo.edge_faces.push_back(corners[i].face);
      topo.face_edges[corners[i].face][corners[i].slot] = e;
    }
  }
  topo.face_offsets.push_back(topo.edge_faces.size());
  return topo;
}

int edge_direction(const Triangle& face, Index a, Index b) {
  for (int k = 0; k < 3; ++k) {
    if (face[k] == a && face[(k + 1) % 3] == b) return 1;
    if (face[k] == b && face[(k + 1) % 3] == a) return -1;
  }
  return 0;
}

}  // namespace vorocrust
