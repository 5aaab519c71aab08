// vorocrust/surface_from_arrays.hpp — an input surface from coordinate and index arrays, for
// programs that hold their meshes in memory (the Python module, FreeCAD's tessellations).
//
// `coordinates` holds three numbers per vertex (x, y, z), `corners` three vertex indices
// (0-based) per triangle. The mesh keeps every vertex and triangle as given and in order, as one
// face group called `name`; `name` is also the source that messages and describe_face() name,
// as a file name is for read_mesh().
//
// Contract as read_mesh's: returns a mesh with at least one triangle, every index in range,
// three distinct corners per triangle and every coordinate finite; otherwise throws
// vorocrust::Error naming `name` and the face or vertex: Usage when an array's length is not a
// multiple of three, UnreadableInput for an index out of range, InvalidGeometry for no
// triangle, a repeated corner or a coordinate that is NaN or infinite.
#pragma once

#include "vorocrust/api.hpp"

#include <cstdint>
#include <span>
#include <string>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

VOROCRUST_API SurfaceMesh surface_from_arrays(std::span<const double> coordinates, std::span<const std::int64_t> corners,
                                const std::string& name);

}  // namespace vorocrust
