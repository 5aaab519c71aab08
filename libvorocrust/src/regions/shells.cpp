#include "regions/shells.hpp"

#include "core/union_find.hpp"
#include "regions/radial_order.hpp"

namespace vorocrust::regions {

Shells join_sides(const SurfaceMesh& mesh, const EdgeTopology& topology) {
  UnionFind sides(2 * mesh.num_faces());
  for (std::size_t e = 0; e < topology.num_edges(); ++e) {
    // Named copies: a lambda may not capture structured bindings before clang 16.
    const Index a = topology.edges[e][0], b = topology.edges[e][1];
    const std::vector<Index> around = faces_around_edge(mesh, a, b, topology.faces_of(e));
    // A face running a -> b has its normal turned the way the angle grows, so its front faces
    // the next wedge; one running b -> a faces it with its back.
    const auto runs_forward = [&](Index f) { return edge_direction(mesh.triangles[f], a, b) > 0; };
    for (std::size_t k = 0; k < around.size(); ++k) {
      const Index f = around[k], g = around[(k + 1) % around.size()];
      const std::size_t leaving = runs_forward(f) ? front_side(f) : back_side(f);
      const std::size_t entering = runs_forward(g) ? back_side(g) : front_side(g);
      sides.unite(static_cast<std::uint32_t>(leaving), static_cast<std::uint32_t>(entering));
    }
  }
  Shells shells;
  shells.of_side.resize(2 * mesh.num_faces());
  for (std::size_t s = 0; s < shells.of_side.size(); ++s) {
    const std::uint32_t root = sides.find(static_cast<std::uint32_t>(s));
    shells.of_side[s] = root == s ? static_cast<Index>(shells.count++) : shells.of_side[root];
  }
  return shells;
}

std::vector<double> shell_volumes(const SurfaceMesh& mesh, const Shells& shells) {
  std::vector<double> six_volume(shells.count, 0.0);
  if (mesh.vertices.empty()) return six_volume;
  const Point origin = mesh.vertices[mesh.triangles.front()[0]];  // well conditioned far from 0
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const double v = (mesh.vertices[t[0]] - origin).dot((mesh.vertices[t[1]] - origin).cross(mesh.vertices[t[2]] - origin));
    // The normal points out of the region behind the face and into the one in front.
    six_volume[shells.of_side[back_side(f)]] += v;
    six_volume[shells.of_side[front_side(f)]] -= v;
  }
  for (double& v : six_volume) v /= 6;
  return six_volume;
}

}  // namespace vorocrust::regions
