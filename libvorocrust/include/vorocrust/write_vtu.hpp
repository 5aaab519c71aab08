// vorocrust/write_vtu.hpp — a VoronoiMesh as a VTK XML unstructured grid (mesh.vtu).
//
// One polyhedron cell (VTK_POLYHEDRON, 42) per Voronoi cell, in the layout VTK 9.1 and ParaView
// read: `faces` and `faceoffsets` arrays beside connectivity, offsets and types, each cell's
// faces oriented outward. Cell data: `material` (the region), `seed` (its seed's index),
// `volume` and `aspect_ratio` (cell_quality.hpp), so that ParaView's Threshold finds the worst
// cells. Arrays are appended raw binary (little-endian, UInt64 headers), produced and written a
// block of cells at a time: beside the mesh, the writer holds a few bytes per cell and point, not
// the file. Written atomically; throws Error(Output) when the file cannot be written.
//
// `quality`: the mesh's measure_cell_quality, when the caller has it; otherwise it is measured
// here (a third of the time compute_cells takes).
#pragma once

#include "vorocrust/api.hpp"

#include <filesystem>

#include "vorocrust/cell_quality.hpp"
#include "vorocrust/cells.hpp"

namespace vorocrust {

VOROCRUST_API void write_vtu(const VoronoiMesh& mesh, const std::filesystem::path& path, const CellQuality* quality = nullptr);

}  // namespace vorocrust
