// Internal: one parser per format, each from a file's bytes to a SurfaceMesh with one group per
// named part. `file` is used in messages and recorded as the groups' source.
#pragma once

#include <string>
#include <string_view>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::io {

SurfaceMesh parse_off(std::string_view bytes, const std::string& file);
SurfaceMesh parse_obj(std::string_view bytes, const std::string& file);
SurfaceMesh parse_stl(std::string_view bytes, const std::string& file);
SurfaceMesh parse_ply(std::string_view bytes, const std::string& file);

// Checks what every reader promises: at least one triangle, indices in range, no repeated
// corner, finite coordinates. Throws Error naming the face's or vertex's line.
void check_parsed_mesh(const SurfaceMesh& mesh, const std::string& file,
                       const std::vector<std::uint32_t>& vertex_lines);

}  // namespace vorocrust::io
