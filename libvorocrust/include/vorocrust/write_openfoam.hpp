// vorocrust/write_openfoam.hpp — a VoronoiMesh as an OpenFOAM case folder.
//
// write_openfoam_case(mesh, dir) writes dir/constant/polyMesh/{points, faces, owner, neighbour,
// boundary, cellZones, faceZones} and dir/system/{controlDict, fvSchemes, fvSolution}, ASCII with FoamFile
// headers, in OpenFOAM's ordering rules: internal faces first, by owner then neighbour (upper
// triangular), then boundary faces grouped by patch; each face's normal points from its owner
// to its neighbour, or out of the domain. Regions are named as region_name() names them, made
// words (characters other than letters, digits and '_' become '_'): the input's names, or
// `outside` (0) and `material<N>`.
// - Boundary faces form one patch per pair of regions, `<owner's region>_to_<region across>`,
//   e.g. `material1_to_outside` or `SKULL_to_AIR`.
// - Faces between two material cells are internal faces, whatever their materials; those between
//   two materials form one face zone per pair, `<lower label>_to_<higher label>` (in
//   constant/polyMesh/faceZones), oriented from the lower label's side: flipMap marks the faces
//   whose owner lies on the higher one's.
// - Cells form one cell zone per material, named after it.
// Each file is written atomically; throws Error(Output) when one cannot be written.
// `checkMesh -case DIR` runs on the result as it is.
#pragma once

#include "vorocrust/api.hpp"

#include <filesystem>

#include "vorocrust/cells.hpp"

namespace vorocrust {

VOROCRUST_API void write_openfoam_case(const VoronoiMesh& mesh, const std::filesystem::path& case_dir);

}  // namespace vorocrust
