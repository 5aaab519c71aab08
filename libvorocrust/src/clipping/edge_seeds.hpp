// Internal: Ebeida and Mitchell's protection of reflex edges (Ebeida and Mitchell 2011, section
// 2.2): seeds on the material's concave sharp edges, so that the clipped cells along them are
// star-shaped about their seeds instead of wrapping round the edge.
//
// Contract of reflex_edge_seeds(domain, material, radius, sharp_angle_degrees, seed):
// - A reflex edge is an edge of exactly two triangles bounding `material` (its region on one side
//   only), the second triangle's far corner outside the first's plane (the material turns
//   concave there), their outward normals more than `sharp_angle_degrees` apart.
// - Every end of a reflex edge takes a seed; then each edge, in input order, takes seeds at random
//   points of its parts farther than r / sqrt(2) from every edge seed so far, until no such part is
//   left (maximal Poisson-disk sampling of the edges at r / sqrt(2)). Edge seeds are then at least
//   r / sqrt(2) apart, and a seed farther than r from all of them is at least r / sqrt(2) from
//   every reflex edge: each point of the edge lies in an edge seed's cell.
// - Each seed moves into the material by a thousandth of r / sqrt(2), in a direction turned a
//   little at random from the faces' inward normals: a seed on the surface, or in the plane of
//   an input face, would put ties in the clipping's side tests. A seed whose way in leaves the
//   material is not placed. The seeds are `material`'s, kind Surface, with radius r / sqrt(2);
//   equal seeds give equal samples.
#pragma once

#include <cstdint>
#include <vector>

#include "vorocrust/seeds.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::clipping {

std::vector<Seed> reflex_edge_seeds(const SurfaceMesh& domain, std::int32_t material, double radius,
                                    double sharp_angle_degrees, std::uint64_t seed);

}  // namespace vorocrust::clipping
