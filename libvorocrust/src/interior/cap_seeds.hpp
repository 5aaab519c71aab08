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
// pole_seeds gives one pole per ball and material on its sphere, in the mean direction of that
// material's seeds there, unless that lands on a surface seed, near one of that material (its
// cell would be a spindle from the centre), or near another pole. A pole is kept only where it
// lies in the material it is placed for (a ray to the surface says so), inside no other ball, and
// clear of the poles already placed. The cells' repairs place more seeds on spheres
// (cells/repair_seeds.hpp).
#pragma once

#include <vector>

#include "vorocrust/seeds.hpp"

namespace vorocrust {

class BallIndex;
class RegionLocator;

std::vector<Seed> pole_seeds(const std::vector<Seed>& surface_seeds, const BallIndex& balls,
                             const RegionLocator& regions);

}  // namespace vorocrust
