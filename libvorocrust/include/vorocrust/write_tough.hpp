// vorocrust/write_tough.hpp — a VoronoiMesh as a TOUGH MESH file (TOUGH2, TOUGH3, TOUGHREACT).
//
// write_tough_mesh(mesh, path) writes the two blocks TOUGH reads from its MESH file, in their
// fixed-width records, each block ended by a blank record:
// - ELEME, one 80-column record per cell: name (5 characters: three of [A-Z0-9], the first a
//   letter, then a right-justified two-digit number, cell k being `code(k / 100)` and `k % 100`),
//   NSEQ and NADD blank, the material (5 characters, see below), the volume (E10.4), AHTX and
//   PMX blank, and the cell's node: its seed, which is where the links between neighbouring
//   cells meet the faces at right angles (E10.4 each of x, y, z).
// - CONNE, one 70-column record per face between two cells: the two names, NSEQ, NAD1, NAD2
//   blank, ISOT (1, 2 or 3: the axis the link between the seeds runs closest to), D1 and D2
//   (the distances from each seed to the face: half the link, the face bisecting it), the face
//   area, and BETAX, the cosine of the angle between gravity (-z) and the link from the first
//   seed to the second (positive when the first lies above).
// Materials are the regions' names (region_name) without their characters outside
// [A-Za-z0-9_]; a longer name than five keeps its start and ends in its label (`region12` gives
// `reg12`, `inside` with label 1 `insi1`); a name left empty or taken becomes `MAT` and the
// label in two digits (`M` and four beyond 99). Numbers are written in the "C" locale whatever the
// process's. Written atomically; throws Error(Output) when the file cannot be written or the
// mesh has more cells than the names can tell apart (3 369 600).
#pragma once

#include "vorocrust/api.hpp"

#include <filesystem>
#include <map>
#include <string>

#include "vorocrust/cells.hpp"

namespace vorocrust {

VOROCRUST_API void write_tough_mesh(const VoronoiMesh& mesh, const std::filesystem::path& path);

// The five-character TOUGH name of cell `cell`, and the material name of each region.
VOROCRUST_API std::string tough_element_name(std::size_t cell);
VOROCRUST_API std::map<std::int32_t, std::string> tough_material_names(const VoronoiMesh& mesh);

}  // namespace vorocrust
