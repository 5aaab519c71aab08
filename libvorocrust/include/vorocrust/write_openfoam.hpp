// vorocrust/write_openfoam.hpp — a VoronoiMesh as an OpenFOAM case folder.
//
// write_openfoam_case(mesh, dir) writes dir/constant/polyMesh/{points, faces, owner, neighbour,
// boundary, cellZones} and dir/system/{controlDict, fvSchemes, fvSolution}, ASCII with FoamFile
// headers, in OpenFOAM's ordering rules: internal faces first, by owner then neighbour (upper
// triangular), then boundary faces grouped by patch; each face's normal points from its owner
// to its neighbour, or out of the domain. Faces between two material cells are internal faces,
// whatever their materials. Boundary faces form one patch per pair of regions, named
// `<owner's region>_to_<region across>` with regions named `outside` (0) and `material<N>`:
// e.g. `material1_to_outside`. Cells form one cell zone per material, `material<N>`. Each file
// is written atomically; throws Error(Output) when one cannot be written. `checkMesh -case DIR`
// runs on the result as it is.
#pragma once

#include <filesystem>

#include "vorocrust/cells.hpp"

namespace vorocrust {

void write_openfoam_case(const VoronoiMesh& mesh, const std::filesystem::path& case_dir);

}  // namespace vorocrust
