#include "vorocrust/surface_mesh.hpp"

#include <filesystem>
#include <utility>

#include "core/c_format.hpp"

namespace vorocrust {

void SurfaceMesh::add_triangle(const Triangle& t, Index group, std::uint32_t line) {
  triangles.push_back(t);
  face_group.push_back(group);
  face_line.push_back(line);
  if (!face_regions.empty()) face_regions.emplace_back();
}

void SurfaceMesh::flip(std::size_t face) {
  std::swap(triangles[face][1], triangles[face][2]);
  if (!face_regions.empty()) std::swap(face_regions[face].back, face_regions[face].front);
}

std::string describe_point(const Point& p) { return c_format("(%.9g, %.9g, %.9g)", p.x(), p.y(), p.z()); }

std::string describe_face(const SurfaceMesh& mesh, std::size_t face) {
  std::string text = "face " + std::to_string(mesh.source_face(face));
  if (face < mesh.face_group.size() && mesh.face_group[face] < mesh.groups.size()) {
    const std::string& file = mesh.groups[mesh.face_group[face]].source_file;
    const std::uint32_t line = face < mesh.face_line.size() ? mesh.face_line[face] : 0;
    if (!file.empty()) {
      text += " (" + std::filesystem::path(file).filename().string();
      if (line > 0) text += " line " + std::to_string(line);
      text += ")";
    }
  }
  return text;
}

}  // namespace vorocrust
