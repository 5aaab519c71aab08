#include "io/polygon.hpp"

#include <cmath>

#include "io/byte_source.hpp"
#include "io/readers.hpp"

namespace vorocrust::io {

void add_polygon(SurfaceMesh& mesh, const PolygonBuffer& corners, Index group, std::uint32_t line,
                 const std::string& file) {
  for (std::size_t i = 0; i < corners.size(); ++i) {
    for (std::size_t j = i + 1; j < corners.size(); ++j) {
      if (corners[i] == corners[j]) {
        fail(Error::Kind::InvalidGeometry, file, line,
             "face repeats vertex " + std::to_string(corners[i]) + ": a triangle needs three distinct corners");
      }
    }
  }
  for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
    mesh.add_triangle({corners[0], corners[k], corners[k + 1]}, group, line);
  }
}

void check_parsed_mesh(const SurfaceMesh& mesh, const std::string& file,
                       const std::vector<std::uint32_t>& vertex_lines) {
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Point& p = mesh.vertices[v];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) {
      const std::size_t line = v < vertex_lines.size() ? vertex_lines[v] : 0;
      fail(Error::Kind::InvalidGeometry, file, line,
           "vertex " + std::to_string(v) + " has a coordinate that is not a finite number (NaN or infinity)");
    }
  }
  if (mesh.triangles.empty()) fail(Error::Kind::InvalidGeometry, file, 0, "empty mesh: the file has no faces");
}

}  // namespace vorocrust::io
