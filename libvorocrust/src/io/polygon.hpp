// Internal: adding a parsed polygon to a mesh. A polygon with repeated corners is an error naming
// its line; one with more than three corners is split into a fan of triangles.
#pragma once

#include <string>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::io {

using PolygonBuffer = std::vector<Index>;

void add_polygon(SurfaceMesh& mesh, const PolygonBuffer& corners, Index group, std::uint32_t line,
                 const std::string& file);

}  // namespace vorocrust::io
