// Internal: the measures of a face polygon and of the cone it spans from a point, over any
// source of points: the welded faces of a mesh (indices into its points) and the faces of cells
// as Voro++ cut them (indices into each cell's own vertices) give the same figures from one code.
//
// `at(k)` is the polygon's k-th point, k < n, in order round it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>

#include "vorocrust/cells.hpp"

namespace vorocrust::geometry {

// Area, unit normal (the right-hand side of the order) and centroid, from the triangles fanned
// about the vertex mean: the same triangles whatever the point the polygon starts at.
template <class PointAt>
FaceGeometry polygon_geometry(std::size_t n, PointAt&& at) {
  Point centre = Point::Zero();
  for (std::size_t k = 0; k < n; ++k) centre += at(k);
  centre /= static_cast<double>(n);
  Point area = Point::Zero(), moment = Point::Zero();
  double fan = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const Point a = at(k), b = at((k + 1) % n);
    const Point twice = (a - centre).cross(b - centre);
    area += twice / 2;
    fan += twice.norm() / 2;
    moment += twice.norm() / 2 * (a + b + centre) / 3;
  }
  FaceGeometry g;
  g.area = area.norm();
  g.normal = g.area > 0 ? Point(area / g.area) : Point::Zero();
  g.centroid = fan > 0 ? Point(moment / fan) : centre;
  return g;
}

// Adds the signed volume of the cone from `apex` over the polygon, fanned about its vertex mean,
// and its first moment: summed over a closed cell's faces, each ordered counter-clockwise seen
// from outside (`outward`, or the reverse order otherwise), they give its volume and centroid.
template <class PointAt>
void add_cone(const Point& apex, std::size_t n, PointAt&& at, bool outward, double& volume, Point& moment) {
  Point centre = Point::Zero();
  for (std::size_t k = 0; k < n; ++k) centre += at(k);
  centre /= static_cast<double>(n);
  for (std::size_t k = 0; k < n; ++k) {
    Point a = at(k), b = at((k + 1) % n);
    if (!outward) std::swap(a, b);
    const double v = (a - centre).cross(b - centre).dot(centre - apex) / 6;
    volume += v;
    moment += v * (apex + centre + a + b) / 4;
  }
}

// Skewness as checkMesh measures it (vorocrust/face_skewness.hpp): the polygon `g` measures,
// between cells whose centroids are `owner` and `neighbour`; a boundary face has no neighbour.
template <class PointAt>
double polygon_skewness(std::size_t n, PointAt&& at, const FaceGeometry& g, const Point& owner,
                        const std::optional<Point>& neighbour) {
  constexpr double kTiny = 1e-300;
  const Point area = g.normal * g.area;
  const Point to_face = g.centroid - owner;
  const Point link = neighbour ? Point(*neighbour - owner) : Point(g.normal * g.normal.dot(to_face));
  const Point off = to_face - area.dot(to_face) / (area.dot(link) + kTiny) * link;
  const Point across = off / (off.norm() + kTiny);
  // A boundary face's link reaches only from the centroid to the face: checkMesh doubles its share.
  double reach = (neighbour ? 0.2 : 0.4) * link.norm() + kTiny;
  for (std::size_t k = 0; k < n; ++k) reach = std::max(reach, std::abs(across.dot(at(k) - g.centroid)));
  return off.norm() / reach;
}

}  // namespace vorocrust::geometry
