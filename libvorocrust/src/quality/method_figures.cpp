#include "vorocrust/method_figures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "quality/histogram_count.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/face_orthogonality.hpp"

namespace vorocrust {
namespace {

constexpr std::size_t kRatioBins = 20;
constexpr double kOffLinkDegrees = 0.05;
constexpr double kConvexTolerance = 1e-6;

// The face's shortest edge over its longest, and the smallest angle at its corners (degrees).
std::pair<double, double> boundary_face_shape(const VoronoiMesh& mesh, const VoronoiFace& face) {
  const std::size_t n = face.points.size();
  double shortest = std::numeric_limits<double>::infinity(), longest = 0, angle = 180;
  for (std::size_t k = 0; k < n; ++k) {
    const Point& prev = mesh.points[face.points[(k + n - 1) % n]];
    const Point& at = mesh.points[face.points[k]];
    const Point& next = mesh.points[face.points[(k + 1) % n]];
    const double length = (next - at).norm();
    shortest = std::min(shortest, length);
    longest = std::max(longest, length);
    const Point a = prev - at, b = next - at;
    angle = std::min(angle, std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / std::numbers::pi);
  }
  return {longest > 0 ? shortest / longest : 0, angle};
}

bool is_convex(const VoronoiMesh& mesh, std::size_t c) {
  const VoronoiCell& cell = mesh.cells[c];
  const double tolerance = kConvexTolerance * std::cbrt(std::abs(cell.volume));
  for (Index f : cell.faces) {
    const FaceGeometry g = face_geometry(mesh, f);
    const Point out = mesh.faces[f].owner == static_cast<std::int32_t>(c) ? g.normal : Point(-g.normal);
    for (Index other : cell.faces) {
      for (Index p : mesh.faces[other].points) {
        if (out.dot(mesh.points[p] - g.centroid) > tolerance) return false;
      }
    }
  }
  return true;
}

}  // namespace

MethodFigures measure_method_figures(const VoronoiMesh& mesh, double enclosed_volume) {
  if (mesh.cells.empty()) throw Error(Error::Kind::InvalidGeometry, "the mesh has no cells to measure");
  MethodFigures m;
  m.cells = mesh.cells.size();
  m.faces = mesh.faces.size();
  m.boundary_edge_ratio_histogram.assign(kRatioBins, 0);
  m.boundary_edge_ratio_min = 1;
  m.boundary_angle_min = 180;
  std::size_t above = 0, face_uses = 0;
  double ratio_sum = 0;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const VoronoiFace& face = mesh.faces[f];
    face_uses += face.neighbour == kNoCell ? 1 : 2;
    if (face.neighbour != kNoCell) {
      const double angle = link_angle(mesh, f);
      m.link_angle_max = std::max(m.link_angle_max, angle);
      m.off_link_faces += angle > kOffLinkDegrees;
      continue;
    }
    ++m.boundary_faces;
    const auto [ratio, corner] = boundary_face_shape(mesh, face);
    ratio_sum += ratio;
    m.boundary_edge_ratio_min = std::min(m.boundary_edge_ratio_min, ratio);
    m.boundary_edge_ratio_below_tenth += ratio < 0.1;
    m.boundary_angle_min = std::min(m.boundary_angle_min, corner);
    quality::count_in_histogram(ratio, 0, 1, m.boundary_edge_ratio_histogram, above);
  }
  m.boundary_edge_ratio_mean = m.boundary_faces ? ratio_sum / static_cast<double>(m.boundary_faces) : 0;
  if (!m.boundary_faces) m.boundary_edge_ratio_min = m.boundary_angle_min = 0;
  m.faces_per_cell = static_cast<double>(face_uses) / static_cast<double>(m.cells);
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    m.volume += mesh.cells[c].volume;
    m.non_convex_cells += !is_convex(mesh, c);
  }
  m.volume_error = enclosed_volume > 0 ? std::abs(m.volume - enclosed_volume) / enclosed_volume : 0;
  return m;
}

}  // namespace vorocrust
