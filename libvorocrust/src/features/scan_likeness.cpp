#include "features/scan_likeness.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/edge_topology.hpp"
#include "core/union_find.hpp"

namespace vorocrust::features {

SharpBends sharp_bends(const SurfaceMesh& mesh, double sharp_angle) {
  const EdgeTopology topology = build_edge_topology(mesh);
  std::vector<Point> normals(mesh.num_faces());
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const Point n = (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    const double length = n.norm();
    normals[f] = length > 0 ? Point(n / length) : Point::Zero();
  }
  SharpBends bends;
  UnionFind chains(mesh.num_vertices());
  std::vector<char> on_chain(mesh.num_vertices(), 0);
  std::vector<std::size_t> sharp;
  for (std::size_t e = 0; e < topology.num_edges(); ++e) {
    if (topology.valence(e) != 2) continue;  // boundary and non-manifold edges are features anyway
    const auto faces = topology.faces_of(e);
    const Point& a = normals[faces[0]];
    const Point& b = normals[faces[1]];
    if (a.isZero() || b.isZero()) continue;
    const double bend = std::atan2(a.cross(b).norm(), a.dot(b));
    if (!(bend > sharp_angle)) continue;
    ++bends.sharp_edges;
    bends.near_sharp_angle += bend < sharp_angle + SharpBends::kNearBend;
    const auto [u, v] = topology.edges[e];
    chains.unite(u, v);
    on_chain[u] = on_chain[v] = 1;
    sharp.push_back(e);
  }
  // Edges per chain, counted at its root (the smallest vertex).
  std::vector<std::size_t> edges_at(mesh.num_vertices(), 0);
  for (std::size_t e : sharp) ++edges_at[chains.find(topology.edges[e][0])];
  std::vector<std::size_t> sizes;
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    if (on_chain[v] && chains.find(v) == v) sizes.push_back(edges_at[v]);
  }
  bends.chains = sizes.size();
  if (!sizes.empty()) {
    std::nth_element(sizes.begin(), sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2), sizes.end());
    bends.median_chain = sizes[sizes.size() / 2];
  }
  return bends;
}

}  // namespace vorocrust::features
