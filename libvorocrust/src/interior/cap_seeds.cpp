// Seeds on the protecting spheres (paper 2.5, section 4): the poles.
#include "interior/cap_seeds.hpp"

#include "interior/sphere_seeds.hpp"

namespace vorocrust {

using namespace interior;

std::vector<Seed> pole_seeds(const std::vector<Seed>& surface_seeds, const BallIndex& balls,
                             const RegionLocator& regions) {
  struct Cap {
    std::int32_t region;
    Point sum;
    int count;
  };
  std::vector<std::vector<Cap>> caps(balls.size());
  std::vector<std::uint32_t> on;
  for (const Seed& s : surface_seeds) {
    if (s.region == kOutsideRegion) continue;
    spheres_through(balls, s.position, s.radius, on);
    for (std::uint32_t b : on) {
      std::vector<Cap>& here = caps[b];
      auto it = std::find_if(here.begin(), here.end(), [&](const Cap& c) { return c.region == s.region; });
      if (it == here.end()) it = here.insert(here.end(), Cap{s.region, Point::Zero(), 0});
      it->sum += (s.position - balls[b].site.position) / balls[b].radius;
      ++it->count;
    }
  }
  // A cap whose seeds lie about one of them (a lone seed, or others symmetric about it) has its
  // pole on that seed, to rounding: the two would be twins, one cell made two by a plane through
  // nearly coincident vertices that no welding tolerance resolves (cgal_bones: a pole 6e-17 from
  // a seed).
  const SeedCloud cloud{&surface_seeds};
  const StaticKdTree<SeedCloud> tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  std::vector<std::uint32_t> near;
  // Whether a seed of the cap's material lies within kPoleClearance of the pole at direction u,
  // or any seed within kPoleOffSeed.
  const auto crowded = [&](std::uint32_t b, const Point& u, std::int32_t region) {
    const Point p = balls[b].site.position + balls[b].radius * u;
    const double clearance = kPoleClearance * balls[b].radius, twin = kPoleOffSeed * balls[b].radius;
    points_within(tree, p, clearance * clearance, near);
    return std::any_of(near.begin(), near.end(), [&](std::uint32_t k) {
      return surface_seeds[k].region == region || (surface_seeds[k].position - p).squaredNorm() < twin * twin;
    });
  };
  SphereSeeds place(balls, regions);
  std::vector<Seed> poles;
  for (std::uint32_t b = 0; b < balls.size(); ++b) {
    for (const Cap& cap : caps[b]) {
      const double length = cap.sum.norm();
      if (!(length > kMinimumMean * cap.count) || crowded(b, cap.sum / length, cap.region)) continue;
      if (const std::optional<Seed> pole = place.place(b, cap.sum / length, cap.region, kPoleSpacing / kSpacing)) {
        poles.push_back(*pole);
      }
    }
  }
  return poles;
}


}  // namespace vorocrust
