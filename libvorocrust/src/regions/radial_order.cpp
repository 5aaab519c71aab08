#include "regions/radial_order.hpp"

#include <algorithm>

#include "geometry/predicates.hpp"

namespace vorocrust::regions {

namespace {

Index third_corner(const Triangle& t, Index a, Index b) {
  for (Index v : t) {
    if (v != a && v != b) return v;
  }
  return t[0];
}

}  // namespace

std::vector<Index> faces_around_edge(const SurfaceMesh& mesh, Index a, Index b, std::span<const Index> faces) {
  std::vector<Index> order(faces.begin(), faces.end());
  if (order.size() < 3) return order;  // one or two faces: every order is the same cycle
  const Point &pa = mesh.vertices[a], &pb = mesh.vertices[b];
  const Point& reference = mesh.vertices[third_corner(mesh.triangles[order[0]], a, b)];
  const Point axis = pb - pa;
  // Quarter of the turn each face lies in: 0 on the reference half-plane, 1 in the open half
  // turn the right-hand rule about a -> b reaches first, 2 on the opposite half-plane, 3 beyond.
  const auto half = [&](Index f) {
    const Point& c = mesh.vertices[third_corner(mesh.triangles[f], a, b)];
    const int side = geometry::orient3d(pa, pb, reference, c);
    if (side > 0) return 1;
    if (side < 0) return 3;
    // In the reference plane: on the reference's half-plane or the opposite one. The two are
    // far apart for any non-degenerate face, so rounding cannot confuse them.
    const Point u = reference - pa, v = c - pa;
    return u.dot(v) * axis.squaredNorm() - u.dot(axis) * v.dot(axis) > 0 ? 0 : 2;
  };
  std::vector<std::pair<int, Index>> keyed;
  keyed.reserve(order.size());
  for (Index f : order) keyed.emplace_back(half(f), f);
  std::stable_sort(keyed.begin(), keyed.end(), [&](const auto& x, const auto& y) {
    if (x.first != y.first) return x.first < y.first;
    if (x.first % 2 == 0) return false;  // on one half-plane: overlapping faces
    // Within one open half turn, y comes later when it lies on the positive side of x's plane.
    const Point& cx = mesh.vertices[third_corner(mesh.triangles[x.second], a, b)];
    const Point& cy = mesh.vertices[third_corner(mesh.triangles[y.second], a, b)];
    return geometry::orient3d(pa, pb, cx, cy) > 0;
  });
  for (std::size_t k = 0; k < keyed.size(); ++k) order[k] = keyed[k].second;
  return order;
}

}  // namespace vorocrust::regions
