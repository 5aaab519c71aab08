#include "seeds/locate_regions.hpp"

#include <array>
#include <cmath>
#include <limits>

#include "vorocrust/seeds.hpp"

namespace vorocrust {

namespace {

// Relative margins below which a hit cannot tell the side: a barycentric coordinate this small
// puts the hit on an edge, where the neighbouring face may be the one that counts.
constexpr double kEdgeMargin = 1e-7;
constexpr double kGrazing = 1e-6;  // |cos| between ray and face normal

}  // namespace

RegionLocator::RegionLocator(const SurfaceMesh& surface) : surface_(surface), faces_(geometry::face_tree(surface)) {}

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

RegionLocator::Hit RegionLocator::first_hit(const Point& p, const Point& direction) const {
  const Point d = direction.normalized();
  Point inverse;
  for (int k = 0; k < 3; ++k) inverse[k] = 1.0 / (std::abs(d[k]) > 1e-300 ? d[k] : 1e-300);
  Hit best{std::numeric_limits<double>::infinity(), 0, false, false};
  const auto crosses = [&](const geometry::Box& box) {  // slab test on [0, best.t]
    double enter = 0, leave = best.t;
    for (int k = 0; k < 3; ++k) {
      double t0 = (box.lo[k] - p[k]) * inverse[k], t1 = (box.hi[k] - p[k]) * inverse[k];
      if (t0 > t1) std::swap(t0, t1);
      enter = std::max(enter, t0);
      leave = std::min(leave, t1);
    }
    return enter <= leave;
  };
  faces_.for_each_where(crosses, [&](std::uint32_t f) {
    const Triangle& tri = surface_.triangles[f];
    const Point &a = surface_.vertices[tri[0]], &b = surface_.vertices[tri[1]], &c = surface_.vertices[tri[2]];
    const Point e1 = b - a, e2 = c - a;
    const Point pv = d.cross(e2);
    const double det = e1.dot(pv);
    const Point normal = e1.cross(e2);
    const double scale = normal.norm();
    if (!(scale > 0)) return;  // degenerate face: its neighbours decide
    const Point tv = p - a;
    const double u = tv.dot(pv) / det;
    const Point qv = tv.cross(e1);
    const double v = d.dot(qv) / det;
    const double t = e2.dot(qv) / det;
    if (!std::isfinite(t) || t <= 0 || t >= best.t) return;
    if (u < -kEdgeMargin || v < -kEdgeMargin || u + v > 1 + kEdgeMargin) return;
    const double cosine = d.dot(normal) / scale;
    const bool clear = std::min({u, v, 1 - u - v}) > kEdgeMargin && std::abs(cosine) > kGrazing;
    best = {t, f, clear, cosine < 0};
  });
  return best;
}

bool RegionLocator::surface_between(const Point& p, const Point& q) const {
  return first_hit(p, q - p).t <= (q - p).norm();
}

std::int32_t RegionLocator::region_of(const Point& p, const Point& direction) const {
  // Directions to fall back on, spread over the sphere and away from the axes, so that a
  // retry does not graze the same axis-aligned faces.
  static const std::array<Point, 6> kFallback = {Point(0.267, 0.534, 0.802), Point(-0.802, 0.267, 0.534),
                                                 Point(0.534, -0.802, 0.267), Point(-0.381, -0.598, 0.705),
                                                 Point(0.705, -0.381, -0.598), Point(-0.598, 0.705, -0.381)};
  Hit hit = first_hit(p, direction);
  for (std::size_t k = 0; !hit.clear && std::isfinite(hit.t) && k < kFallback.size(); ++k) {
    hit = first_hit(p, kFallback[k]);
  }
  if (!std::isfinite(hit.t)) return kOutsideRegion;
  return hit.from_front ? region_in_front(hit.face) : region_behind(hit.face);
}

}  // namespace vorocrust
