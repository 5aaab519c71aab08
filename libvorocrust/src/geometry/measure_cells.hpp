// Internal: the volume and centroid of every cell of a mesh, from its faces fanned about their
// vertex means: the same triangles on both sides of a face, so the volumes add up to the volume
// the boundary encloses. Every cell must have a face.
#pragma once

#include "vorocrust/cells.hpp"

namespace vorocrust::geometry {

void measure_cells(VoronoiMesh& mesh);

}  // namespace vorocrust::geometry
