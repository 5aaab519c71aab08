// The volume quality of the paper's section 3: per cell the aspect ratio (smallest enclosing
// sphere over largest inscribed ball), volume, face count and shortest edge; then the figures
// over all cells.
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "quality/cell_parts.hpp"
#include "quality/histogram_count.hpp"
#include "quality/face_figures.hpp"
#include "geometry/cell_spheres.hpp"
#include "vorocrust/cell_quality.hpp"
#include "vorocrust/face_skewness.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust {

void CellQualityOptions::check() const {
  if (histogram_bins < 1 || histogram_bins > 1000) {
    throw Error(Error::Kind::Usage,
                "the aspect-ratio histogram needs 1 to 1000 bins, got " + std::to_string(histogram_bins));
  }
  if (!(histogram_high > 1) || !std::isfinite(histogram_high)) {
    throw Error(Error::Kind::Usage, "the aspect-ratio histogram must end above 1, got " + std::to_string(histogram_high));
  }
  if (threads < 0) throw Error(Error::Kind::Usage, "threads must be 0 (all) or more, got " + std::to_string(threads));
}

namespace {

void check_cell(const VoronoiMesh& mesh, std::size_t c) {
  const auto fail = [&](const std::string& why) {
    throw Error(Error::Kind::InvalidGeometry, "cell " + std::to_string(c) + " " + why);
  };
  const VoronoiCell& cell = mesh.cells[c];
  if (cell.faces.empty()) fail("has no faces");
  for (Index f : cell.faces) {
    if (f >= mesh.faces.size()) fail("names face " + std::to_string(f) + " of " + std::to_string(mesh.faces.size()));
    if (mesh.faces[f].points.size() < 3) fail("has face " + std::to_string(f) + " with fewer than three points");
    for (Index p : mesh.faces[f].points) {
      if (p >= mesh.points.size()) fail("has point " + std::to_string(p) + " of " + std::to_string(mesh.points.size()));
    }
  }
}

CellShape measure_cell(const VoronoiMesh& mesh, const VoronoiCell& cell) {
  CellShape shape;
  shape.volume = cell.volume;
  shape.faces = cell.faces.size();

  std::vector<Index> ids;
  shape.shortest_edge = std::numeric_limits<double>::infinity();
  for (Index f : cell.faces) {
    const std::vector<Index>& polygon = mesh.faces[f].points;
    for (std::size_t k = 0; k < polygon.size(); ++k) {
      ids.push_back(polygon[k]);
      const double edge = (mesh.points[polygon[k]] - mesh.points[polygon[(k + 1) % polygon.size()]]).norm();
      shape.shortest_edge = std::min(shape.shortest_edge, edge);
    }
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  std::vector<Point> points;
  points.reserve(ids.size());
  for (Index p : ids) points.push_back(mesh.points[p]);
  const geometry::CellSpheres spheres = geometry::cell_spheres(
      std::move(points), cell.faces.size(), [&](std::size_t f) { return mesh.faces[cell.faces[f]].points.size(); },
      [&](std::size_t f, std::size_t k) -> const Point& { return mesh.points[mesh.faces[cell.faces[f]].points[k]]; });
  shape.circumcentre = spheres.outer.centre;
  shape.circumradius = spheres.outer.radius;
  shape.incentre = spheres.inner.centre;
  shape.inradius = spheres.inner.radius;
  shape.aspect_ratio = spheres.aspect_ratio();
  shape.shortest_edge_relative = cell.volume > 0 ? shape.shortest_edge / std::cbrt(cell.volume) : 0;
  return shape;
}

void summarise(const VoronoiMesh& mesh, const CellQualityOptions& options, CellQuality& q) {
  const std::size_t n = q.cells.size();
  q.histogram_high = options.histogram_high;
  q.aspect_ratio_histogram.assign(options.histogram_bins, 0);
  const double inf = std::numeric_limits<double>::infinity();
  q.min_aspect_ratio = q.min_volume = q.min_shortest_edge_relative = inf;
  q.max_aspect_ratio = q.max_volume = -inf;
  q.min_faces = std::numeric_limits<std::size_t>::max();
  double ratio_sum = 0, faces_sum = 0, edge_sum = 0;
  for (std::size_t c = 0; c < n; ++c) {
    const CellShape& s = q.cells[c];
    q.min_aspect_ratio = std::min(q.min_aspect_ratio, s.aspect_ratio);
    if (s.aspect_ratio > q.max_aspect_ratio) {
      q.max_aspect_ratio = s.aspect_ratio;
      q.worst_cell = c;
    }
    ratio_sum += s.aspect_ratio;
    quality::count_in_histogram(s.aspect_ratio, q.histogram_low, q.histogram_high, q.aspect_ratio_histogram,
                                q.aspect_ratio_above_high);
    q.min_volume = std::min(q.min_volume, s.volume);
    q.max_volume = std::max(q.max_volume, s.volume);
    q.total_volume += s.volume;
    q.min_faces = std::min(q.min_faces, s.faces);
    q.max_faces = std::max(q.max_faces, s.faces);
    faces_sum += static_cast<double>(s.faces);
    if (s.shortest_edge_relative < q.min_shortest_edge_relative) {
      q.min_shortest_edge_relative = s.shortest_edge_relative;
      q.shortest_edge_cell = c;
    }
    edge_sum += s.shortest_edge_relative;
  }
  const double count = static_cast<double>(n);
  q.mean_aspect_ratio = ratio_sum / count;
  q.mean_faces = faces_sum / count;
  q.mean_shortest_edge_relative = edge_sum / count;
  q.worst_seed = mesh.cells[q.worst_cell].seed;
}

}  // namespace

CellQuality measure_cell_quality(const VoronoiMesh& mesh, const CellQualityOptions& options) {
  options.check();
  if (mesh.cells.empty()) throw Error(Error::Kind::InvalidGeometry, "the mesh has no cells to measure");
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) check_cell(mesh, c);
  CellQuality q;
  q.cells.resize(mesh.cells.size());
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, mesh.cells.size(),
                      [&](std::size_t c) { q.cells[c] = measure_cell(mesh, mesh.cells[c]); });
  });
  summarise(mesh, options, q);
  quality::measure_cell_parts(mesh, arena, q);
  struct FaceFigures {
    double skewness = 0, link_angle = 0, non_orthogonality = 0;
  };
  std::vector<FaceFigures> faces(mesh.faces.size());
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, mesh.faces.size(), [&](std::size_t f) {
      // The face's geometry once for its three figures.
      const VoronoiFace& face = mesh.faces[f];
      const FaceGeometry g = face_geometry(mesh, f);
      faces[f].skewness = quality::face_skewness(mesh, f, g);
      if (face.neighbour == kNoCell) return;
      const VoronoiCell &owner = mesh.cells[face.owner], &neighbour = mesh.cells[face.neighbour];
      faces[f].link_angle = quality::angle_to_link(g.normal, owner.site, neighbour.site);
      faces[f].non_orthogonality = quality::angle_to_link(g.normal, owner.centroid, neighbour.centroid);
    });
  });
  double cosine_sum = 0;  // checkMesh's mean is the angle of the mean cosine
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (faces[f].skewness > q.max_skewness) q.max_skewness = faces[f].skewness, q.most_skew_face = f;
    q.highly_skew_faces += faces[f].skewness > kHighSkewness;
    if (faces[f].link_angle > q.max_link_angle) q.max_link_angle = faces[f].link_angle, q.link_angle_face = f;
    q.max_non_orthogonality = std::max(q.max_non_orthogonality, faces[f].non_orthogonality);
    if (mesh.faces[f].neighbour != kNoCell) cosine_sum += std::cos(faces[f].non_orthogonality * std::numbers::pi / 180);
  }
  const std::size_t interior = count_interior_faces(mesh);
  const double mean_cosine = interior > 0 ? cosine_sum / static_cast<double>(interior) : 1;
  q.mean_non_orthogonality = std::acos(std::clamp(mean_cosine, -1.0, 1.0)) * 180 / std::numbers::pi;
  return q;
}

}  // namespace vorocrust
