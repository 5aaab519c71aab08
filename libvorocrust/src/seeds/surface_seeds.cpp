// Surface seeds and the output surface (paper 2.4).
#include "seeds/surface_seeds.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace vorocrust {

SurfaceSeeds surface_seeds(const BallIndex& balls, const std::vector<SeedPair>& pairs, const RegionLocator& regions) {
  SurfaceSeeds out;
  out.seeds.resize(2 * pairs.size());
  // Each seed looks for its side towards its partner: the surface passes between the two, so
  // the first face is near and met at a steep angle.
  tbb::parallel_for(std::size_t{0}, pairs.size(), [&](std::size_t i) {
    const SeedPair& pair = pairs[i];
    double radius = 0;
    for (std::uint32_t b : pair.balls) radius += balls[b].radius / 3;
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
  return out;
}

}  // namespace vorocrust
