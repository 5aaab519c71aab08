// Internal: clipped Voronoi cells (Yan, Wang, Lévy and Liu 2011, sections 4.1-4.2; Ebeida and
// Mitchell 2011, section 3): every material cell of a Voronoi mesh intersected with the material's
// region of the input, assembled into one conforming polyhedral mesh.
//
// Contract of clip_cells(voronoi, domain, material):
// - `voronoi` is compute_cells' mesh of seeds that lie inside `material`'s region, bounded by
//   outside seeds so far away that every face toward one lies outside the region (an outside
//   seed farther from every point of the region than that point's nearest material seed).
// - `domain` carries its regions (label_regions); the faces between `material` and any other
//   region bound it. Every other region is outside: one material per run.
// - The result's cells are the seeds' cells in the same order. Faces between two cells are the
//   parts of their Voronoi faces inside the region, one face per connected part; the boundary
//   faces are the parts of the input triangles inside each cell (the surface's restricted
//   Voronoi diagram), so the boundary reproduces the input exactly; a cell's parts side by side
//   in one plane of one input group are joined into one face. Every point is computed
//   once, from what defines it (an input vertex; an input edge and a bisector; an input triangle
//   and two bisectors; a Voronoi vertex), and shared by every face that has it: cells are closed,
//   and their volumes add up to the region's.
// - Cells inside the region are kept as they are: convex, their faces orthogonal to the seed
//   links. Clipped cells need not be convex; their faces between cells keep the orthogonality.
//
// A face's part with holes (a corner of the outside poking through a Voronoi face) is cut into
// simple polygons between its own points (polygon_holes.hpp).
//
// Where the outside seeds come so near that part of the surface lies in their cells, the result is
// empty and stats->uncovered_triangles counts the triangles concerned (move them farther). The
// figures are vorocrust/stats.hpp's ClippingStats. Throws
// Error(InvalidGeometry) where a face toward an outside seed reaches inside the region.
#pragma once

#include <cstddef>
#include <cstdint>

#include "vorocrust/cells.hpp"
#include "vorocrust/stats.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::clipping {

VoronoiMesh clip_cells(const VoronoiMesh& voronoi, const SurfaceMesh& domain, std::int32_t material,
                       ClippingStats* stats = nullptr);

}  // namespace vorocrust::clipping
