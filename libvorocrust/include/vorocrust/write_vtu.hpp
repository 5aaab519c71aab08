// vorocrust/write_vtu.hpp — a VoronoiMesh as a VTK XML unstructured grid (mesh.vtu).
//
// One polyhedron cell (VTK_POLYHEDRON, 42) per Voronoi cell, in the layout VTK 9.1 and ParaView
// read: `faces` and `faceoffsets` arrays beside connectivity, offsets and types, each cell's
// faces oriented outward. Cell data: `material` (the region), `seed` (its seed's index) and
// `volume`. Arrays are appended raw binary (little-endian, UInt64 headers). Written atomically;
// throws Error(Output) when the file cannot be written.
#pragma once

#include <filesystem>

#include "vorocrust/cells.hpp"

namespace vorocrust {

void write_vtu(const VoronoiMesh& mesh, const std::filesystem::path& path);

}  // namespace vorocrust
