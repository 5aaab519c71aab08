// Internal: every cell's edges, faces and dihedral angles against the cell's size, summed over
// the boundary layer and the interior (vorocrust/cell_quality.hpp says what each figure is).
#pragma once

#include <tbb/task_arena.h>

#include "vorocrust/cell_quality.hpp"
#include "vorocrust/cells.hpp"

namespace vorocrust::quality {

// Fills q.boundary_layer and q.interior, running in `arena`. The cells are taken in blocks of a
// fixed size and the blocks' sums added in cell order, so the figures do not depend on the
// thread count.
void measure_cell_parts(const VoronoiMesh& mesh, tbb::task_arena& arena, CellQuality& q);

}  // namespace vorocrust::quality
