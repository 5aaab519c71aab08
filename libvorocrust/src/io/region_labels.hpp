// Internal: region labels carried by group names. A group named "BACK|FRONT" separates region
// BACK (behind its faces) from region FRONT (the side their normals point to).
#pragma once

#include <string>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::io {

// Index of `name` in mesh.region_names, appending it when new.
std::int32_t region_index(SurfaceMesh& mesh, const std::string& name);

// Fills face_regions from group names of the form "BACK|FRONT"; leaves the mesh unlabelled when
// no group is named so.
void assign_regions_from_group_names(SurfaceMesh& mesh);

}  // namespace vorocrust::io
