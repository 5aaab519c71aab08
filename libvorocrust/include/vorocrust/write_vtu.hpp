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
//
// write_tets_vtu(mesh, path) writes the tetrahedra dual to a clipped mesh's cells (Yan et al.
// 2011, 5.2: the Delaunay tetrahedra of the seeds whose circumcentre lies inside their material)
// as tets.vtu: one point per cell at its seed (point data `seed`), one VTK_TETRA (10) per
// tetrahedron, positively oriented, with cell data `material`, `min_dihedral` and
// `max_dihedral` (degrees), `radius_ratio` and `q4` (their Table 2's Q1 to Q4). Same layout,
// atomicity and errors as mesh.vtu.
#pragma once

#include "vorocrust/api.hpp"

#include <filesystem>

#include "vorocrust/cell_quality.hpp"
#include "vorocrust/cells.hpp"

namespace vorocrust {

VOROCRUST_API void write_vtu(const VoronoiMesh& mesh, const std::filesystem::path& path, const CellQuality* quality = nullptr);
VOROCRUST_API void write_tets_vtu(const VoronoiMesh& mesh, const std::filesystem::path& path);

}  // namespace vorocrust
