// Internal: Ebeida and Mitchell's uniform random seeds (Ebeida and Mitchell 2011, section 2):
// maximal Poisson-disk sampling of a material's region at one radius r. No two seeds are closer
// than r, and no point of the region is farther than r from a seed, up to slivers along the
// surface thinner than r / 100 where the refinement stops. Unbiased: every point of the region
// not yet within r of a seed is as likely as any other to take the next seed.
//
// Contract of poisson_disk_seeds(domain, material, radius, seed, placed): `domain` carries its
// regions (label_regions); `placed` seeds (seeds on reflex edges, then a lattice) come first in
// the result, but for lattice (interior) points within r of an edge seed, and the sampling fills
// what they leave, at least r from all of them. A background grid of cubes of side r / sqrt(3) (each holds one seed at
// most) takes darts in random live cubes; then every cube no seed's ball covers whole is split in eight and the darts
// go on among the parts, down to a 64th of the side. Cubes the surface may cross take darts only at points inside the
// material (a ray decides). Equal seeds give equal samples. The seeds are interior seeds of `material`, with `radius`
// as their radius.
//
// outside_seeds(domain, margin, spacing) gives seeds on a box `margin` beyond the domain's, at
// most `spacing` apart: outside seeds that bound every cell. They keep clear of the material
// (clip_cells' condition) when every point of it lies within `margin` of a material seed: a
// margin of 1.5 r does for a maximal sample of radius r.
#pragma once

#include <cstdint>
#include <vector>

#include "vorocrust/seeds.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::clipping {

std::vector<Seed> poisson_disk_seeds(const SurfaceMesh& domain, std::int32_t material, double radius,
                                     std::uint64_t seed, const std::vector<Seed>& placed = {});

std::vector<Seed> outside_seeds(const SurfaceMesh& domain, double margin, double spacing);

}  // namespace vorocrust::clipping
