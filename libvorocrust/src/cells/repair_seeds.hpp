// Internal: seeds that repair the cells, on the protecting spheres where they can go (the room
// and spacing rules of interior/sphere_seeds.hpp):
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
#include "vorocrust/seeds.hpp"

namespace vorocrust {

class BallIndex;
class RegionLocator;

// A seed at the centroid of each of `long_cells` (cells of `seeds` whose aspect ratio is too
// large: cells::GrowingCells::long_cells), pushed out of the balls to 1.15 radii, where it still lies nearer the
// centroid than the cell's seed does and in the cell's material, clear of `placed` (the seeds on
// spheres and the repairs). It halves a spindle: a seed on a sphere beside others of its material
// has a cell from the ball's centre deep into the interior, which no interior seed reaches within
// the balls' clearance. Where the centroid so pushed would lie no nearer it than the seed, the
// point halfway from the centroid to the cell's vertex farthest from the seed is tried the same
// way. A cell thinner than the balls beside it, as in a thin wall between two sheets, has both
// inside them and keeps its shape.
std::vector<Seed> aspect_split_seeds(const std::vector<cells::LongCell>& long_cells, const std::vector<Seed>& seeds,
                                     const BallIndex& balls, const RegionLocator& regions,
                                     const std::vector<Seed>& placed);

// `skew` are the highly skew faces of the cells of `seeds` (cells::GrowingCells::skew_faces);
// `placed` the cap seeds among the seeds.
std::vector<Seed> skew_repair_seeds(const std::vector<cells::CutFace>& skew, const std::vector<Seed>& seeds,
                                    const BallIndex& balls, const RegionLocator& regions,
                                    const std::vector<Seed>& placed);

}  // namespace vorocrust
