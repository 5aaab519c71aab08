#include "vorocrust/surface_from_arrays.hpp"

#include "io/byte_source.hpp"
#include "io/polygon.hpp"
#include "io/readers.hpp"

namespace vorocrust {

SurfaceMesh surface_from_arrays(std::span<const double> coordinates, std::span<const std::int64_t> corners,
                                const std::string& name) {
  if (coordinates.size() % 3 != 0) {
    io::fail(Error::Kind::Usage, name, 0,
             "the vertex array holds " + std::to_string(coordinates.size()) +
                 " numbers, not three (x, y, z) per vertex");
  }
  if (corners.size() % 3 != 0) {
    io::fail(Error::Kind::Usage, name, 0,
             "the triangle array holds " + std::to_string(corners.size()) +
                 " indices, not three per triangle");
  }
  if (corners.empty()) io::fail(Error::Kind::InvalidGeometry, name, 0, "empty mesh: no triangles");

  SurfaceMesh mesh;
  mesh.groups.push_back({name, name});
  const std::size_t num_vertices = coordinates.size() / 3;
  mesh.vertices.reserve(num_vertices);
  for (std::size_t v = 0; v < num_vertices; ++v) {
    mesh.vertices.emplace_back(coordinates[3 * v], coordinates[3 * v + 1], coordinates[3 * v + 2]);
  }
  mesh.triangles.reserve(corners.size() / 3);
  io::PolygonBuffer triangle(3);
  for (std::size_t f = 0; f < corners.size() / 3; ++f) {
    for (std::size_t k = 0; k < 3; ++k) {
      const std::int64_t index = corners[3 * f + k];
      if (index < 0 || static_cast<std::uint64_t>(index) >= num_vertices) {
        throw Error(Error::Kind::UnreadableInput,
                    "triangle " + std::to_string(f) + " has vertex index " + std::to_string(index) +
                        ", out of range: there are " + std::to_string(num_vertices) + " vertices (0-based)",
                    {.file = name, .face = f});
      }
      triangle[k] = static_cast<Index>(index);
    }
    io::add_polygon(mesh, triangle, 0, 0, name);
  }
  io::check_parsed_mesh(mesh, name, {});
  return mesh;
}

}  // namespace vorocrust
