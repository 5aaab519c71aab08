#include "core/surface_measures.hpp"

namespace vorocrust {

Point unit_normal(const std::vector<Point>& vertices, const Triangle& t) {
  const Point n = (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]);
  const double length = n.norm();
  return length > 0 ? Point(n / length) : Point(Point::Zero());
}

Point face_normal(const SurfaceMesh& mesh, Index face) { return unit_normal(mesh.vertices, mesh.triangles[face]); }

double face_area(const SurfaceMesh& mesh, Index face) {
  const Triangle& t = mesh.triangles[face];
  return 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).norm();
}

Point face_centroid(const SurfaceMesh& mesh, Index face) {
  const Triangle& t = mesh.triangles[face];
  return (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3;
}

double surface_area(const SurfaceMesh& mesh, const std::vector<Index>& faces) {
  double area = 0;
  for (Index f : faces) area += face_area(mesh, f);
  return area;
}

double bounding_box_diagonal(const SurfaceMesh& mesh) {
  Eigen::AlignedBox3d box;
  for (const Triangle& t : mesh.triangles) {
    for (Index v : t) box.extend(mesh.vertices[v]);
  }
  return box.isEmpty() ? 0 : box.diagonal().norm();
}

double enclosed_volume(const SurfaceMesh& mesh, const std::vector<Index>& faces) {
  if (faces.empty()) return 0;
  const Point origin = mesh.vertices[mesh.triangles[faces.front()][0]];
  double six_volume = 0;
  for (Index f : faces) {
    const Triangle& t = mesh.triangles[f];
    six_volume += (mesh.vertices[t[0]] - origin).dot((mesh.vertices[t[1]] - origin).cross(mesh.vertices[t[2]] - origin));
  }
  return six_volume / 6.0;
}

}  // namespace vorocrust
