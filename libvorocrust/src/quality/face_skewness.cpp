// Face skewness as checkMesh defines it (OpenFOAM's primitiveMesh face skewness).
#include "vorocrust/face_skewness.hpp"

#include <optional>

#include <tbb/parallel_for.h>

#include "geometry/polygon_measures.hpp"
#include "quality/face_figures.hpp"

namespace vorocrust {

double quality::face_skewness(const VoronoiMesh& mesh, std::size_t face, const FaceGeometry& g) {
  const VoronoiFace& f = mesh.faces[face];
  const auto at = [&](std::size_t k) -> const Point& { return mesh.points[f.points[k]]; };
  const std::optional<Point> neighbour =
      f.neighbour != kNoCell ? std::optional<Point>(mesh.cells[f.neighbour].centroid) : std::nullopt;
  return geometry::polygon_skewness(f.points.size(), at, g, mesh.cells[f.owner].centroid, neighbour);
}

double face_skewness(const VoronoiMesh& mesh, std::size_t face) {
  return quality::face_skewness(mesh, face, face_geometry(mesh, face));
}

std::vector<std::size_t> skew_faces(const VoronoiMesh& mesh, double threshold) {
  std::vector<char> skew(mesh.faces.size(), 0);
  tbb::parallel_for(std::size_t{0}, mesh.faces.size(),
                    [&](std::size_t f) { skew[f] = face_skewness(mesh, f) > threshold; });
  std::vector<std::size_t> out;
  for (std::size_t f = 0; f < skew.size(); ++f) {
    if (skew[f]) out.push_back(f);
  }
  return out;
}

}  // namespace vorocrust
