// vorocrust/write_pflotran.hpp — a VoronoiMesh as a PFLOTRAN explicit unstructured grid.
//
// write_pflotran(mesh, folder) writes into `folder`:
// - mesh.uge, for GRID TYPE UNSTRUCTURED_EXPLICIT: `CELLS n`, then per cell `id x y z volume`
//   (ids from 1 in cell order; x y z the seed, where the links between neighbouring cells cross
//   the faces at right angles), then `CONNECTIONS m`, then per face between two cells
//   `id1 id2 x y z area` (x y z the face's centroid);
// - <material>.txt per material: its cells' ids, one a line, for a REGION's FILE;
// - <patch>.ex per pair of regions on the boundary (named as write_openfoam_case names its
//   patches, `material1_to_outside`): `CONNECTIONS k`, then per boundary face
//   `id x y z area`, for boundary conditions.
// Material and patch names are region_name()'s, made words. Numbers are written in the shortest
// form that reads back exactly, in the "C" locale whatever the process's. Each file is written
// atomically; throws Error(Output) when one cannot be.
#pragma once

#include "vorocrust/api.hpp"

#include <filesystem>

#include "vorocrust/cells.hpp"

namespace vorocrust {

VOROCRUST_API void write_pflotran(const VoronoiMesh& mesh, const std::filesystem::path& folder);

}  // namespace vorocrust
