#include "geometry/ray_cast.hpp"

#include <algorithm>
#include <cmath>

namespace vorocrust::geometry {

namespace {

constexpr double kEdgeMargin = 1e-7;  // barycentric coordinate below which a hit is on an edge
constexpr double kGrazing = 1e-6;     // |cos| between ray and face normal below which it grazes

}  // namespace

template <class Limit, class Visit>
void RayCaster::cast(const Point& p, const Point& direction, Limit&& limit, Visit&& visit) const {
  const Point d = direction.normalized();
  Point inverse;
  for (int k = 0; k < 3; ++k) inverse[k] = 1.0 / (std::abs(d[k]) > 1e-300 ? d[k] : 1e-300);
  const auto crosses = [&](const Box& box) {  // slab test on [0, limit]
    double enter = 0, leave = limit();
    for (int k = 0; k < 3; ++k) {
      double t0 = (box.lo[k] - p[k]) * inverse[k], t1 = (box.hi[k] - p[k]) * inverse[k];
      if (t0 > t1) std::swap(t0, t1);
      enter = std::max(enter, t0);
      leave = std::min(leave, t1);
    }
    return enter <= leave;
  };
  faces_.for_each_where(crosses, [&](std::uint32_t f) {
    const Triangle& tri = mesh_.triangles[f];
    const Point &a = mesh_.vertices[tri[0]], &b = mesh_.vertices[tri[1]], &c = mesh_.vertices[tri[2]];
    const Point e1 = b - a, e2 = c - a;
    const Point pv = d.cross(e2);
    const double det = e1.dot(pv);
    const Point normal = e1.cross(e2);
    const double scale = normal.norm();
    if (!(scale > 0)) return;
    const Point tv = p - a;
    const double u = tv.dot(pv) / det;
    const Point qv = tv.cross(e1);
    const double v = d.dot(qv) / det;
    const double t = e2.dot(qv) / det;
    if (!std::isfinite(t) || t <= 0 || t >= limit()) return;
    if (u < -kEdgeMargin || v < -kEdgeMargin || u + v > 1 + kEdgeMargin) return;
    const double cosine = d.dot(normal) / scale;
    const bool clear = std::min({u, v, 1 - u - v}) > kEdgeMargin && std::abs(cosine) > kGrazing;
    visit(RayHit{t, f, clear, cosine < 0});
  });
}

RayHit RayCaster::first_hit(const Point& p, const Point& direction) const {
  RayHit best;
  cast(p, direction, [&] { return best.t; }, [&](const RayHit& hit) { best = hit; });
  return best;
}

std::vector<RayHit> RayCaster::all_hits(const Point& p, const Point& direction) const {
  std::vector<RayHit> hits;
  cast(p, direction, [] { return std::numeric_limits<double>::infinity(); },
       [&](const RayHit& hit) { hits.push_back(hit); });
  std::sort(hits.begin(), hits.end(),
            [](const RayHit& a, const RayHit& b) { return a.t < b.t || (a.t == b.t && a.face < b.face); });
  return hits;
}

}  // namespace vorocrust::geometry
