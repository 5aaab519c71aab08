// Internal: the region of space a point lies in, read off the first input face a ray from the
// point meets. Faces carry the regions on their two sides (SurfaceMesh::face_regions); a surface
// without labels bounds one material, inside its faces' backs.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "geometry/ray_cast.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

class RegionLocator {
 public:
  explicit RegionLocator(const SurfaceMesh& surface);

  // The region on p's side of the first face the ray from p along `direction` meets, or
  // kOutsideRegion when the ray meets none. A hit too near an edge or too grazing to decide the
  // side is retried along other directions. Thread-safe.
  std::int32_t region_of(const Point& p, const Point& direction) const;
  // The same along a fixed direction, for points no direction suits better.
  std::int32_t region_of(const Point& p) const { return region_of(p, Point(0.48, 0.6, 0.64)); }

  // Whether the segment from p to q meets an input face: two seeds of one region on either side
  // of an open sheet do, two seeds on one side of a closed surface do not. Thread-safe.
  bool surface_between(const Point& p, const Point& q) const;

  std::int32_t region_behind(Index face) const;
  std::int32_t region_in_front(Index face) const;
  // The names of the labels above: the surface's own, or "outside" and "inside".
  std::vector<std::string> region_names() const;

 private:
  const SurfaceMesh& surface_;
  geometry::RayCaster rays_;
};

}  // namespace vorocrust
