#include "check_balls/surface_locator.hpp"

#include <algorithm>

namespace vorocrust::checker {

double distance_to_segment(const Point& x, const Point& a, const Point& b) {
  const Point ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0 ? std::clamp((x - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (x - (a + t * ab)).norm();
}

double distance_to_triangle(const Point& x, const Point& a, const Point& b, const Point& c) {
  const Point n = (b - a).cross(c - a);
  const double n2 = n.squaredNorm();
  if (n2 > 0) {
    const Point q = x - ((x - a).dot(n) / n2) * n;  // projection on the triangle's plane
    const bool inside = (b - a).cross(q - a).dot(n) >= 0 && (c - b).cross(q - b).dot(n) >= 0 &&
                        (a - c).cross(q - c).dot(n) >= 0;
    if (inside) return (x - q).norm();
  }
  return std::min({distance_to_segment(x, a, b), distance_to_segment(x, b, c), distance_to_segment(x, c, a)});
}

SurfaceLocator::SurfaceLocator(const SurfaceMesh& mesh, const Strata& strata) : mesh_(mesh), strata_(strata) {
  std::vector<Point> centres;
  std::vector<double> radii;
  for (Index v : strata.corner_vertex) centres.push_back(mesh.vertices[v]), radii.push_back(0);
  corners_ = SphereIndex(centres, radii);

  centres.clear(), radii.clear();
  for (Index e = 0; e < strata.edges.size(); ++e) {
    if (!strata.sharp[e]) continue;
    const Point& a = mesh.vertices[strata.edges[e].a];
    const Point& b = mesh.vertices[strata.edges[e].b];
    sharp_edges_.push_back(e);
    centres.push_back(0.5 * (a + b));
    radii.push_back(0.5 * (b - a).norm());
  }
  sharp_edges_index_ = SphereIndex(centres, radii);

  // Each face within the sphere around its centroid through its farthest corner.
  centres.clear(), radii.clear();
  for (const Triangle& t : mesh.triangles) {
    const Point c = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
    double r = 0;
    for (Index v : t) r = std::max(r, (mesh.vertices[v] - c).norm());
    centres.push_back(c);
    radii.push_back(r * (1 + 1e-12));
  }
  faces_ = SphereIndex(centres, radii);
}

template <class Distance>
Nearest SurfaceLocator::nearest(const SphereIndex& index, const Point& x, double slack, Distance&& distance) const {
  Nearest result;
  if (index.empty()) return result;
  // An upper bound from a few candidates, then every element that could beat it.
  double bound = std::numeric_limits<double>::infinity();
  index.for_each_group_nearest(x, [&](Index i) { bound = std::min(bound, distance(i)); });
  std::vector<std::pair<double, Index>> candidates;
  index.for_each_near(x, bound + slack, [&](Index i, double) {
    const double d = distance(i);
    if (d <= bound + slack) candidates.emplace_back(d, i);
  });
  for (const auto& [d, i] : candidates) result.distance = std::min(result.distance, d);
  for (const auto& [d, i] : candidates) {
    if (d <= result.distance + slack) result.elements.push_back(i);
  }
  std::sort(result.elements.begin(), result.elements.end());
  return result;
}

Nearest SurfaceLocator::nearest_corner(const Point& x, double slack) const {
  return nearest(corners_, x, slack,
                 [&](Index k) { return (x - mesh_.vertices[strata_.corner_vertex[k]]).norm(); });
}

Nearest SurfaceLocator::nearest_sharp_edge(const Point& x, double slack) const {
  Nearest n = nearest(sharp_edges_index_, x, slack, [&](Index i) {
    const SurfaceEdge& e = strata_.edges[sharp_edges_[i]];
    return distance_to_segment(x, mesh_.vertices[e.a], mesh_.vertices[e.b]);
  });
  for (Index& i : n.elements) i = sharp_edges_[i];
  return n;
}

Nearest SurfaceLocator::nearest_face(const Point& x, double slack) const {
  return nearest(faces_, x, slack, [&](Index f) {
    const Triangle& t = mesh_.triangles[f];
    return distance_to_triangle(x, mesh_.vertices[t[0]], mesh_.vertices[t[1]], mesh_.vertices[t[2]]);
  });
}

}  // namespace vorocrust::checker
