// Internal: clipped Voronoi cells (Yan, Wang, Lévy and Liu 2011, sections 4.1-4.2; Ebeida and
// Mitchell 2011, section 3): every material cell of a Voronoi mesh intersected with the material's
// region of the input, assembled into one conforming polyhedral mesh.
//
// Contract of clip_cells(voronoi, domain):
// - `voronoi` holds one Voronoi diagram per material, side by side: each material's cells (their
//   region) are compute_cells' cells of that material's seeds, which lie inside its region, and
//   of outside seeds so far away that every face toward one lies outside the region (an outside
//   seed farther from every point of the region than that point's nearest material seed). No
//   face joins two diagrams; a diagram's points are its own.
// - `domain` carries its regions (label_regions). Every region with cells is a material; the
//   others are outside. Faces with one region on both sides (sheets) are not cut along.
// - The result's cells are the input's, in the same order. Faces between two cells of a material
//   are the parts of their Voronoi faces inside its region, one face per connected part; the
//   boundary faces are the parts of the input triangles inside each cell (the surface's
//   restricted Voronoi diagram), so the boundary reproduces the input exactly; on a triangle
//   between two materials, each part in one cell of each material is a face between the two (the
//   overlay of both diagrams), so the materials conform along their interface. A cell's parts
//   side by side in one plane of one input group, toward the same cell or the outside, are
//   joined into one face. Every point is computed once, from what defines it (an input vertex; an
//   input edge and a bisector; an input triangle and two bisectors; a Voronoi vertex), and shared
//   by every face that has it: cells are closed, and their volumes add up to the regions'.
// - Cells inside their region are kept as they are: convex, their faces orthogonal to the seed
//   links. Clipped cells need not be convex; their faces between cells of one material keep the
//   orthogonality (faces on an interface lie in the input's plane instead).
//
// A face's part with holes (a corner of the outside poking through a Voronoi face) is cut into
// simple polygons between its own points (polygon_holes.hpp).
//
// Where the outside seeds come so near that part of the surface lies in their cells, the result is
// empty and stats->uncovered_triangles counts the triangles concerned (move them farther). The
// figures are vorocrust/stats.hpp's ClippingStats. Throws
// Error(InvalidGeometry) where a face toward an outside seed reaches inside the region.
//
// material_diagrams(seeds, materials_end, threads) builds that input: `seeds` holds the material
// seeds first (up to materials_end, grouped by material), then the outside seeds; each material's
// diagram is compute_cells' of its own seeds and the outside seeds. Cells are numbered as their
// seeds, points diagram by diagram.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "vorocrust/cells.hpp"
#include "vorocrust/seeds.hpp"
#include "vorocrust/stats.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::clipping {

VoronoiMesh clip_cells(const VoronoiMesh& voronoi, const SurfaceMesh& domain, ClippingStats* stats = nullptr);

VoronoiMesh material_diagrams(const std::vector<Seed>& seeds, std::size_t materials_end, int threads = 0);

}  // namespace vorocrust::clipping
