#include "refinement/union_cover.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace vorocrust {

bool segment_covered(const Point& a, const Point& b, const std::vector<CoverBall>& balls) {
  const Point d = b - a;
  const double length2 = d.squaredNorm();
  if (length2 == 0) return false;
  // Each ball covers the parameter interval where |a + t d - c| <= r.
  std::vector<std::pair<double, double>> intervals;
  for (const CoverBall& ball : balls) {
    const Point f = a - ball.centre;
    const double half_b = f.dot(d) / length2, c = (f.squaredNorm() - ball.radius * ball.radius) / length2;
    const double disc = half_b * half_b - c;
    if (disc < 0) continue;
    const double root = std::sqrt(disc);
    intervals.emplace_back(-half_b - root, -half_b + root);
  }
  std::sort(intervals.begin(), intervals.end());
  double reached = 0;
  for (const auto& [lo, hi] : intervals) {
    if (lo > reached) return false;
    reached = std::max(reached, hi);
    if (reached >= 1) return true;
  }
  return false;
}

namespace {

// A ball's section by the plane of a triangle.
struct Disc {
  Point centre;  // in the plane
  double radius2;
};

// Points where segment pq (in the disc's plane) crosses the disc's circle. Crossings a rounding
// error beyond an end still count: an extra point only makes the cover test stricter.
// At most two points, without allocating.
struct Crossings {
  std::array<Point, 2> points;
  int count = 0;
  void push_back(const Point& p) { points[count++] = p; }
  const Point* begin() const { return points.data(); }
  const Point* end() const { return points.data() + count; }
};

void crossings(const Point& p, const Point& q, const Disc& disc, Crossings& out) {
  const Point d = q - p, f = p - disc.centre;
  const double a = d.squaredNorm();
  if (a == 0) return;
  const double half_b = f.dot(d) / a, c = (f.squaredNorm() - disc.radius2) / a;
  const double discriminant = half_b * half_b - c;
  if (discriminant < 0) return;
  const double root = std::sqrt(discriminant);
  for (double t : {-half_b - root, -half_b + root}) {
    if (t >= -1e-9 && t <= 1 + 1e-9) out.push_back(p + t * d);
  }
}

// Points where two circles of one plane (with normal `normal`) cross.
void circle_crossings(const Disc& first, const Disc& second, const Point& normal, Crossings& out) {
  const Point offset = second.centre - first.centre;
  const double d2 = offset.squaredNorm();
  if (d2 == 0) return;
  const double along = (d2 + first.radius2 - second.radius2) / (2 * d2);  // in units of the offset
  const double across2 = first.radius2 / d2 - along * along;
  if (across2 < 0) return;
  const Point middle = first.centre + along * offset;
  const Point side = std::sqrt(across2) * normal.cross(offset) / normal.norm();
  out.push_back(middle + side);
  out.push_back(middle - side);
}

// Whether p (in the triangle's plane) lies in the triangle or a rounding error outside it.
bool near_triangle(const Point& p, const Point& a, const Point& b, const Point& c, const Point& normal) {
  const double slack = -1e-9 * normal.squaredNorm();
  return (b - a).cross(p - a).dot(normal) >= slack && (c - b).cross(p - b).dot(normal) >= slack &&
         (a - c).cross(p - c).dot(normal) >= slack;
}

}  // namespace

// The balls cut T's plane in discs. If some point of T lay in no disc, the lowest point of the
// uncovered set's closure under a generic linear function would be a corner of T, a point where
// an edge of T crosses a circle, or a point where two circles cross: it cannot lie on one circle
// alone or inside an edge, where the function still decreases along the boundary. None of those
// points lies inside any disc. So T is covered when each such point that is in T lies strictly
// inside a disc — one other than the discs it lies on, which holds it only on its boundary.
// (Rounding may put such a point a hair inside its own circle: the discs it lies on are skipped.)
bool triangle_covered(const Point& a, const Point& b, const Point& c, const std::vector<CoverBall>& balls) {
  const Point normal = (b - a).cross(c - a);
  const double n2 = normal.squaredNorm();
  if (n2 == 0) return false;
  // More balls than this over one piece come only with pieces far larger than the balls, which
  // splitting serves better: such a piece counts as not covered.
  constexpr std::size_t kMaxDiscs = 48;
  std::array<Disc, kMaxDiscs> discs;
  std::size_t count = 0;
  for (const CoverBall& ball : balls) {
    const double h = (ball.centre - a).dot(normal) / n2;
    const double rho2 = ball.radius * ball.radius - h * h * n2;
    if (!(rho2 > 0)) continue;
    if (count == kMaxDiscs) return false;
    discs[count++] = {Point(ball.centre - h * normal), rho2};
  }
  const auto inside_another = [&](const Point& p, std::size_t skip1, std::size_t skip2) {
    for (std::size_t k = 0; k < count; ++k) {
      if (k != skip1 && k != skip2 && (p - discs[k].centre).squaredNorm() < discs[k].radius2) return true;
    }
    return false;
  };
  constexpr std::size_t kNone = ~std::size_t{0};
  const Point* corners[3] = {&a, &b, &c};
  for (const Point* corner : corners) {
    if (!inside_another(*corner, kNone, kNone)) return false;
  }
  for (std::size_t i = 0; i < count; ++i) {
    for (int e = 0; e < 3; ++e) {
      Crossings points;
      crossings(*corners[e], *corners[(e + 1) % 3], discs[i], points);
      for (const Point& p : points) {
        if (!inside_another(p, i, kNone)) return false;
      }
    }
  }
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t j = i + 1; j < count; ++j) {
      Crossings points;
      circle_crossings(discs[i], discs[j], normal, points);
      for (const Point& p : points) {
        if (near_triangle(p, a, b, c, normal) && !inside_another(p, i, j)) return false;
      }
    }
  }
  return true;
}

}  // namespace vorocrust
