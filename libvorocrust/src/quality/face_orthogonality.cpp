// The angle between a face of a Voronoi mesh and the link across it, against seeds or centroids.
#include "vorocrust/face_orthogonality.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "quality/face_figures.hpp"

namespace vorocrust {

namespace quality {

double angle_to_link(const Point& normal, const Point& from, const Point& to) {
  const Point link = to - from;
  const double length = link.norm();
  if (!(length > 0) || normal.isZero()) return 0;  // no direction to turn from
  const double cosine = std::clamp(normal.dot(link) / length, -1.0, 1.0);
  // atan2 of the sine and cosine stays exact for the tiny angles this is mostly about.
  return std::atan2(normal.cross(link).norm() / length, cosine) * 180 / std::numbers::pi;
}

}  // namespace quality

double link_angle(const VoronoiMesh& mesh, std::size_t face) {
  const VoronoiFace& f = mesh.faces[face];
  if (f.owner == kNoCell || f.neighbour == kNoCell) return 0;
  return quality::angle_to_link(face_geometry(mesh, face).normal, mesh.cells[f.owner].site,
                                mesh.cells[f.neighbour].site);
}

double centroid_non_orthogonality(const VoronoiMesh& mesh, std::size_t face) {
  const VoronoiFace& f = mesh.faces[face];
  if (f.owner == kNoCell || f.neighbour == kNoCell) return 0;
  return quality::angle_to_link(face_geometry(mesh, face).normal, mesh.cells[f.owner].centroid,
                                mesh.cells[f.neighbour].centroid);
}

}  // namespace vorocrust
