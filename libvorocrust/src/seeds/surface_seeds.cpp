// Surface seeds and the output surface (paper 2.4).
#include "seeds/surface_seeds.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "seeds/near_twins.hpp"

namespace vorocrust {

namespace {

// Seeds of one region nearer each other than kTwin radii are one seed. Sliver elimination
// parts such twins (seeds/near_twins.hpp) for a few rounds; any left after those go here, which
// moves the cells' boundary off their pairs' facets by about that much. Cells of seeds so near
// may not assemble otherwise (cgal_bones: two seeds 4.2e-5 radii apart).

// Marks the later seed of each pair of twins of one region.
std::vector<char> later_twins(const std::vector<Seed>& seeds) {
  std::vector<Point> positions(seeds.size());
  std::vector<double> radii(seeds.size());
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    positions[i] = seeds[i].position;
    radii[i] = seeds[i].radius;
  }
  std::vector<char> twin(seeds.size(), 0);
  for (const auto& [i, j] : twin_pairs(positions, radii)) {
    if (seeds[i].region == seeds[j].region) twin[j] = 1;
  }
  return twin;
}

}  // namespace

SurfaceSeeds surface_seeds(const BallIndex& balls, const std::vector<SeedPair>& pairs, const RegionLocator& regions) {
  SurfaceSeeds out;
  out.seeds.resize(2 * pairs.size());
  // Each seed looks for its side towards its partner: the surface passes between the two, so
  // the first face is near and met at a steep angle.
  tbb::parallel_for(std::size_t{0}, pairs.size(), [&](std::size_t i) {
    const SeedPair& pair = pairs[i];
    const double radius = mean_radius(balls, pair);
    for (int k = 0; k < 2; ++k) {
      const Point& p = pair.points[k];
      out.seeds[2 * i + k] = {p, regions.region_of(p, pair.points[1 - k] - p), radius, SeedKind::Surface};
    }
  });

  // A pair whose seeds share a region bounds the surface only across an open sheet; elsewhere
  // (both points of a triplet on one side, where the surface curves tightly) it bounds nothing.
  std::vector<char> bounds_surface(pairs.size());
  tbb::parallel_for(std::size_t{0}, pairs.size(), [&](std::size_t i) {
    bounds_surface[i] = out.seeds[2 * i].region != out.seeds[2 * i + 1].region ||
                        regions.surface_between(pairs[i].points[0], pairs[i].points[1]);
  });
  std::vector<Index> vertex_of(balls.size(), static_cast<Index>(-1));
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (!bounds_surface[i]) continue;
    for (std::uint32_t b : pairs[i].balls) vertex_of[b] = 0;
  }
  SurfaceMesh& surface = out.surface;
  for (std::uint32_t b = 0; b < balls.size(); ++b) {
    if (vertex_of[b] == 0) {
      vertex_of[b] = static_cast<Index>(surface.vertices.size());
      surface.vertices.push_back(balls[b].site.position);
    }
  }
  surface.groups.push_back({"surface", ""});
  surface.region_names = regions.region_names();
  std::vector<RegionPair> face_regions;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (!bounds_surface[i]) continue;
    const std::int32_t front = out.seeds[2 * i].region, back = out.seeds[2 * i + 1].region;
    const auto& b = pairs[i].balls;
    // The triangle (b0, b1, b2) faces points[0], the seed of region `front`.
    Triangle t{vertex_of[b[0]], vertex_of[b[1]], vertex_of[b[2]]};
    RegionPair regions_of_face{back, front};
    if (front > back) {
      std::swap(t[1], t[2]);
      std::swap(regions_of_face.back, regions_of_face.front);
    }
    surface.add_triangle(t, 0);
    face_regions.push_back(regions_of_face);
  }
  surface.face_regions = std::move(face_regions);
  // Twins go once the surface is made: every pair still gives its facet.
  const std::vector<char> twin = later_twins(out.seeds);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < out.seeds.size(); ++i) {
    if (!twin[i]) out.seeds[kept++] = out.seeds[i];
  }
  out.seeds.resize(kept);
  return out;
}

}  // namespace vorocrust
