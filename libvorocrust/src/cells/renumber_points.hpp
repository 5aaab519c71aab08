// Internal: a mesh's points numbered in the order its faces first use them, so that work over the
// mesh in cell order finds them close together; points no face uses are dropped (welding and
// clipping leave such points).
#pragma once

#include "vorocrust/cells.hpp"

namespace vorocrust::cells {

void renumber_points(VoronoiMesh& mesh);

}  // namespace vorocrust::cells
