#include "seeds/locate_regions.hpp"

#include <array>
#include <cmath>
#include <limits>

#include "vorocrust/seeds.hpp"

namespace vorocrust {

RegionLocator::RegionLocator(const SurfaceMesh& surface) : surface_(surface), rays_(surface) {}

std::int32_t RegionLocator::region_behind(Index face) const {
  return surface_.has_regions() ? surface_.face_regions[face].back : kInsideRegion;
}

std::int32_t RegionLocator::region_in_front(Index face) const {
  return surface_.has_regions() ? surface_.face_regions[face].front : kOutsideRegion;
}

std::vector<std::string> RegionLocator::region_names() const {
  if (surface_.has_regions()) return surface_.region_names;
  std::vector<std::string> names(2);
  names[kOutsideRegion] = "outside";
  names[kInsideRegion] = "inside";
  return names;
}

bool RegionLocator::surface_between(const Point& p, const Point& q) const {
  return rays_.first_hit(p, q - p).t <= (q - p).norm();
}

std::int32_t RegionLocator::region_of(const Point& p, const Point& direction) const {
  geometry::RayHit hit = rays_.first_hit(p, direction);
  for (std::size_t k = 0; !hit.clear && hit.found() && k < geometry::kGenericDirections.size(); ++k) {
    const auto& g = geometry::kGenericDirections[k];
    hit = rays_.first_hit(p, Point(g[0], g[1], g[2]));
  }
  if (!hit.found()) return kOutsideRegion;
  return hit.from_front ? region_in_front(hit.face) : region_behind(hit.face);
}

}  // namespace vorocrust
