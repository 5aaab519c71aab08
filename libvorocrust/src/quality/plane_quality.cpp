// Figures of a 2D mesh: angles, aspect ratio, short edges, orthogonality to the seed links,
// convexity, area per region.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/predicates.hpp"
#include "geometry/small_lp.hpp"
#include "vorocrust/plane.hpp"

namespace vorocrust {

namespace {

// The smallest circle enclosing the points (Welzl's algorithm, iterative form).
double enclosing_radius(std::vector<Point2> pts) {
  Point2 c = pts[0];
  double r = 0;
  const auto from2 = [](const Point2& a, const Point2& b, Point2& c2, double& r2) {
    c2 = (a + b) / 2;
    r2 = (a - b).norm() / 2;
  };
  const auto from3 = [](const Point2& a, const Point2& b, const Point2& p, Point2& c3, double& r3) {
    const Point2 ab = b - a, ap = p - a;
    const double d = 2 * (ab.x() * ap.y() - ab.y() * ap.x());
    if (d == 0) {
      // Collinear: the widest pair.
      Point2 lo = a, hi = b;
      if ((p - a).norm() > (hi - lo).norm()) hi = p;
      if ((p - b).norm() > (hi - lo).norm()) lo = b, hi = p;
      c3 = (lo + hi) / 2;
      r3 = (hi - lo).norm() / 2;
      return;
    }
    const double ux = (ap.y() * ab.squaredNorm() - ab.y() * ap.squaredNorm()) / d;
    const double uy = (ab.x() * ap.squaredNorm() - ap.x() * ab.squaredNorm()) / d;
    c3 = a + Point2(ux, uy);
    r3 = Point2(ux, uy).norm();
  };
  const double slack = 1 + 1e-12;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if ((pts[i] - c).norm() <= r * slack) continue;
    c = pts[i];
    r = 0;
    for (std::size_t j = 0; j < i; ++j) {
      if ((pts[j] - c).norm() <= r * slack) continue;
      from2(pts[i], pts[j], c, r);
      for (std::size_t k = 0; k < j; ++k) {
        if ((pts[k] - c).norm() <= r * slack) continue;
        from3(pts[i], pts[j], pts[k], c, r);
      }
    }
  }
  return r;
}

// The largest circle inside a convex polygon (counter-clockwise): its centre x and radius t
// maximise t with every edge's line at least t away, a linear program, solved on the polygon
// moved to its first vertex and scaled to size one (the solver's tolerances are absolute).
double inscribed_radius(const std::vector<Point2>& ring) {
  const std::size_t n = ring.size();
  double scale = 0;
  for (const Point2& p : ring) scale = std::max(scale, (p - ring[0]).norm());
  if (!(scale > 0)) return 0;
  std::vector<geometry::HalfSpace> edges;
  for (std::size_t k = 0; k < n; ++k) {
    const Point2 a = (ring[k] - ring[0]) / scale, e = (ring[(k + 1) % n] - ring[k]) / scale;
    if (e.norm() == 0) continue;
    const Point2 outward = Point2(e.y(), -e.x()).normalized();
    geometry::HalfSpace h;
    h.a = {outward.x(), outward.y(), 1, 0};
    h.b = outward.dot(a);
    edges.push_back(h);
  }
  const std::optional<geometry::LpVector> best = geometry::maximise(3, {0, 0, 1, 0}, edges, 4);
  return best ? (*best)[2] * scale : 0;
}

}  // namespace

PlaneQuality measure_plane_quality(const PlaneMesh& mesh) {
  PlaneQuality q;
  q.cells = mesh.cells.size();
  q.min_angle = 180;
  q.min_shortest_edge = std::numeric_limits<double>::infinity();
  double sum_aspect = 0;
  for (const PlaneCell& cell : mesh.cells) {
    const std::size_t n = cell.points.size();
    std::vector<Point2> ring;
    for (Index v : cell.points) ring.push_back(mesh.points[v]);
    const double size = std::sqrt(std::abs(cell.area));
    const Point2 seed(mesh.seeds[cell.seed].position.x(), mesh.seeds[cell.seed].position.y());
    for (std::size_t k = 0; k < n; ++k) {
      const Point2 &a = ring[(k + n - 1) % n], &b = ring[k], &c = ring[(k + 1) % n];
      if (geometry::orient2d(a.x(), a.y(), b.x(), b.y(), c.x(), c.y()) < 0) q.convex = false;
      const double angle = std::acos(std::clamp((a - b).normalized().dot((c - b).normalized()), -1.0, 1.0)) * 180 / std::numbers::pi;
      q.min_angle = std::min(q.min_angle, angle);
      q.max_angle = std::max(q.max_angle, angle);
      const double length = (c - b).norm();
      q.min_shortest_edge = std::min(q.min_shortest_edge, length / size);
      // Each edge between two cells is counted once, from the lower cell.
      const std::int32_t other = cell.across[k];
      const bool first_side = other == kNoCell || static_cast<Index>(other) > static_cast<Index>(&cell - mesh.cells.data());
      if (!first_side) continue;
      ++q.edges;
      if (length / size < 0.01) ++q.edges_below_0_01;
      if (length / size < 0.1) ++q.edges_below_0_1;
      if (other == kNoCell) {
        ++q.boundary_edges;
        continue;
      }
      if (cell.regions_across[k] != cell.region) ++q.interface_edges;
      const Point& s = mesh.seeds[mesh.cells[static_cast<std::size_t>(other)].seed].position;
      const Point2 link = Point2(s.x(), s.y()) - seed;
      const double cosine = std::abs(link.normalized().dot((c - b).normalized()));
      q.max_link_angle = std::max(q.max_link_angle, std::asin(std::min(1.0, cosine)) * 180 / std::numbers::pi);
    }
    const double aspect = enclosing_radius(ring) / inscribed_radius(ring);
    q.aspect_ratio.push_back(aspect);
    q.max_aspect_ratio = std::max(q.max_aspect_ratio, aspect);
    sum_aspect += aspect;
    if (static_cast<std::size_t>(cell.region) >= q.area_by_region.size()) q.area_by_region.resize(static_cast<std::size_t>(cell.region) + 1, 0);
    q.area_by_region[static_cast<std::size_t>(cell.region)] += cell.area;
  }
  q.mean_aspect_ratio = q.cells ? sum_aspect / static_cast<double>(q.cells) : 0;
  return q;
}

}  // namespace vorocrust
