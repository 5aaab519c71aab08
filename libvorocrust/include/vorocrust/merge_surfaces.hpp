// vorocrust/merge_surfaces.hpp — several surfaces as one model, as read_meshes() merges files.
//
// Each part is a solid or sheet of its own (one input file, one FreeCAD object): its groups
// become groups of the model, named after the part (`name` when the part has one group,
// `name/group` when it has several), so a later stage can tell the parts apart. A vertex with
// exactly the coordinates of a vertex of an earlier part is shared, so parts that touch along
// common faces stay connected; vertices repeated within one part stay as that part has them.
// Region labels carried by the parts are kept, their names merged by name.
//
// Throws Error(Usage) when `parts` is empty.
#pragma once

#include "vorocrust/api.hpp"

#include <span>
#include <string>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

struct VOROCRUST_API NamedSurface {
  std::string name;
  SurfaceMesh mesh;
};

VOROCRUST_API SurfaceMesh merge_surfaces(std::span<const NamedSurface> parts);

}  // namespace vorocrust
