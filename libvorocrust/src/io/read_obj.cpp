#include <string>

#include "io/byte_source.hpp"
#include "io/polygon.hpp"
#include "io/readers.hpp"
#include "io/region_labels.hpp"

namespace vorocrust::io {

namespace {

// The vertex part of an OBJ face corner "v", "v/t", "v//n" or "v/t/n".
std::string_view vertex_part(std::string_view corner) {
  const std::size_t slash = corner.find('/');
  return slash == std::string_view::npos ? corner : corner.substr(0, slash);
}

}  // namespace

SurfaceMesh parse_obj(std::string_view bytes, const std::string& file) {
  LineCursor in(bytes, file);
  SurfaceMesh mesh;
  std::vector<std::uint32_t> vertex_lines;
  const std::string stem = std::filesystem::path(file).stem().string();
  // Faces before any `o`/`g` line belong to a group named after the file.
  std::string current_name = stem;
  Index current_group = 0;
  bool group_open = false;
  std::vector<std::int64_t> raw_corners;  // OBJ indices as written, resolved after reading
  struct PendingFace {
    std::size_t first_corner, corners;
    Index group;
    std::uint32_t line;
  };
  std::vector<PendingFace> pending;

  while (in.next_nonempty()) {
    const std::string_view keyword = in.token();
    if (keyword == "v") {
      const double x = in.require_double("an x coordinate");
      const double y = in.require_double("a y coordinate");
      const double z = in.require_double("a z coordinate");
      mesh.vertices.emplace_back(x, y, z);
      vertex_lines.push_back(static_cast<std::uint32_t>(in.line_number()));
    } else if (keyword == "f") {
      if (!group_open) {
        current_group = static_cast<Index>(mesh.groups.size());
        mesh.groups.push_back({current_name, file});
        group_open = true;
      }
      const std::size_t first = raw_corners.size();
      for (std::string_view corner = in.token(); !corner.empty(); corner = in.token()) {
        std::int64_t index = 0;
        if (!parse_int(vertex_part(corner), index)) {
          in.fail(Error::Kind::UnreadableInput, "expected a vertex index, found " + quote(corner));
        }
        if (index == 0) in.fail(Error::Kind::UnreadableInput, "vertex index 0 is not valid: OBJ counts from 1");
        // Negative indices count back from the last vertex read so far.
        if (index < 0) {
          index += static_cast<std::int64_t>(mesh.vertices.size()) + 1;
          if (index < 1) {
            in.fail(Error::Kind::UnreadableInput, "relative vertex index " + std::string(vertex_part(corner)) +
                                                      " reaches before the first vertex");
          }
        }
        raw_corners.push_back(index);
      }
      const std::size_t corners = raw_corners.size() - first;
      if (corners < 3) {
        in.fail(Error::Kind::UnreadableInput, "a face needs at least 3 corners, this one has " + std::to_string(corners));
      }
      pending.push_back({first, corners, current_group, static_cast<std::uint32_t>(in.line_number())});
    } else if (keyword == "g" || keyword == "o") {
      const std::string_view name = in.rest_of_line();
      current_name = name.empty() ? stem : std::string(name);
      // Consecutive faces with one name form one group; a name used again continues its group.
      group_open = false;
      for (Index g = 0; g < mesh.groups.size(); ++g) {
        if (mesh.groups[g].name == current_name) {
          current_group = g;
          group_open = true;
        }
      }
    }
    // vt, vn, l, p, s, usemtl, mtllib and unknown statements carry nothing a surface needs.
  }

  // Indices may refer to vertices defined later in the file, so they are checked at the end.
  PolygonBuffer polygon;
  for (const PendingFace& face : pending) {
    polygon.clear();
    for (std::size_t k = 0; k < face.corners; ++k) {
      const std::int64_t index = raw_corners[face.first_corner + k];
      if (index > static_cast<std::int64_t>(mesh.vertices.size())) {
        fail(Error::Kind::UnreadableInput, file, face.line,
             "face refers to vertex " + std::to_string(index) + " but the file has only " +
                 std::to_string(mesh.vertices.size()) + " vertices");
      }
      polygon.push_back(static_cast<Index>(index - 1));
    }
    add_polygon(mesh, polygon, face.group, face.line, file);
  }
  assign_regions_from_group_names(mesh);
  check_parsed_mesh(mesh, file, vertex_lines);
  return mesh;
}

}  // namespace vorocrust::io
