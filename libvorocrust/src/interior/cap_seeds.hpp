// Internal: seeds on the protecting spheres, which keep the cells about each ball's centre well
// shaped (paper 2.5 leaves the interior ours to seed; its section 4 names the short Voronoi edges
// and skew faces these remove).
//
// Every seed on a ball's sphere lies at the ball's radius from its centre, so the centre is a
// Voronoi vertex of all their cells, and their faces through it are the duals of the sphere's
// Delaunay edges. The inner seeds of a smooth patch form a ring on the sphere, nearly on one
// circle: the Delaunay triangulation of a nearly flat ring has edges between nearly coplanar
// triangles, each a narrow face through the centre between two surface cells whose centroids lie
// far to its sides, the faces checkMesh calls highly skew. A seed on the sphere in the middle of
// the ring (its pole) replaces those edges by edges to itself. Seeds near a sphere but off it
// are the other source: they cut small faces about the centre; the interior sampler keeps its
// seeds out of a clearance around every ball for that reason.
//
// - pole_seeds: one pole per ball and material on its sphere, in the mean direction of that
//   material's seeds there, unless that lands on a surface seed, near one of that material (its
//   cell would be a spindle from the centre), or near another pole;
// - skew_repair_seeds: where a face of the cells is still highly skew, between two cells of one
//   material: if it is a wedge through the centre of a sphere both seeds lie on, a seed on that
//   sphere toward the face, or else at its free point farthest from the material's seeds there;
//   else a seed toward the face on a sphere either seed lies on; where no sphere takes one, a
//   seed at the face's centroid, pushed out of the balls; where that is no nearer the face than
//   the cells' seeds, a seed at the centroid of the cell whose centroid lies farther from its
//   seed, which splits it. Faces between two seeds on spheres are split first;
// - aspect_split_seeds: a seed splitting each cell of too large an aspect ratio.
// A seed is kept only where it lies in the material it is placed for (a ray to the surface says
// so), inside no other ball, and clear of the seeds already placed this way. A skew face those
// rules leave without a seed tries again with its seed allowed just outside the other balls and
// spaced from those placed at its own scale: beside a ball far larger than the face's seeds, the
// large ball's clearance and its pole's spacing can cover all the room there is.
#pragma once

#include <vector>

#include "cells/growing_cells.hpp"
#include "vorocrust/cells.hpp"
#include "vorocrust/seeds.hpp"

namespace vorocrust {

class BallIndex;
class RegionLocator;

std::vector<Seed> pole_seeds(const std::vector<Seed>& surface_seeds, const BallIndex& balls,
                             const RegionLocator& regions);

// A seed at the centroid of each of `long_cells` (cells of `seeds` whose aspect ratio is too
// large: cells::GrowingCells::long_cells), pushed out of the balls to 1.15 radii, where it still lies nearer the
// centroid than the cell's seed does and in the cell's material, clear of `placed` (the seeds on
// spheres and the repairs). It halves a spindle: a seed on a sphere beside others of its material
// has a cell from the ball's centre deep into the interior, which no interior seed reaches within
// the balls' clearance. A cell thinner than the balls beside it, as in a thin wall between two
// sheets, has its centroid inside them and keeps its shape.
std::vector<Seed> aspect_split_seeds(const std::vector<cells::LongCell>& long_cells, const std::vector<Seed>& seeds,
                                     const BallIndex& balls, const RegionLocator& regions,
                                     const std::vector<Seed>& placed);

// `skew` are the highly skew faces of the cells of `seeds` (cells::GrowingCells::skew_faces);
// `placed` the cap seeds among the seeds.
std::vector<Seed> skew_repair_seeds(const std::vector<cells::CutFace>& skew, const std::vector<Seed>& seeds,
                                    const BallIndex& balls, const RegionLocator& regions,
                                    const std::vector<Seed>& placed);

}  // namespace vorocrust
