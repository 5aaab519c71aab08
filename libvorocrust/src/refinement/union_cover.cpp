#include "refinement/union_cover.hpp"

#include <algorithm>
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

bool inside(const Point& p, const CoverBall& ball) { return (p - ball.centre).squaredNorm() <= ball.radius * ball.radius; }

// Points where segment pq crosses the sphere of `ball`.
void crossings(const Point& p, const Point& q, const CoverBall& ball, std::vector<Point>& out) {
  const Point d = q - p, f = p - ball.centre;
  const double a = d.squaredNorm();
  if (a == 0) return;
  const double half_b = f.dot(d) / a, c = (f.squaredNorm() - ball.radius * ball.radius) / a;
  const double disc = half_b * half_b - c;
  if (disc < 0) return;
  const double root = std::sqrt(disc);
  for (double t : {-half_b - root, -half_b + root}) {
    if (t >= 0 && t <= 1) out.push_back(p + t * d);
  }
}

bool in_triangle(const Point& p, const Point& a, const Point& b, const Point& c, const Point& normal) {
  return (b - a).cross(p - a).dot(normal) >= 0 && (c - b).cross(p - b).dot(normal) >= 0 &&
         (a - c).cross(p - c).dot(normal) >= 0;
}

}  // namespace

// T is covered by D1 u D2 (Di the balls cut by T's plane) exactly when T \ D1 lies in D2. The
// distance to the second centre is convex, so its maximum over the closure of T \ D1 is taken at
// an extreme point of that set: a corner of T outside D1, a point where an edge of T crosses the
// first circle, or the point of the first circle farthest from the second centre, when in T.
bool triangle_covered_by_two(const Point& a, const Point& b, const Point& c, const CoverBall& first,
                             const CoverBall& second) {
  const Point normal = (b - a).cross(c - a);
  const double n2 = normal.squaredNorm();
  if (n2 == 0) return false;
  std::vector<Point> extreme;
  for (const Point* corner : {&a, &b, &c}) {
    if (!inside(*corner, first)) extreme.push_back(*corner);
  }
  if (extreme.empty()) return true;  // T lies in the first ball
  crossings(a, b, first, extreme);
  crossings(b, c, first, extreme);
  crossings(c, a, first, extreme);
  // The first circle: centre and radius of the sphere's section by T's plane.
  const double h = (first.centre - a).dot(normal) / n2;
  const Point centre = first.centre - h * normal;
  const double rho2 = first.radius * first.radius - h * h * n2;
  if (rho2 > 0) {
    const Point second_in_plane = second.centre - ((second.centre - a).dot(normal) / n2) * normal;
    Point away = centre - second_in_plane;
    if (away.squaredNorm() > 0) {
      const Point far = centre + std::sqrt(rho2) * away.normalized();
      if (in_triangle(far, a, b, c, normal)) extreme.push_back(far);
    }
  }
  const double limit = second.radius * second.radius;
  for (const Point& p : extreme) {
    if ((p - second.centre).squaredNorm() > limit) return false;
  }
  return true;
}

}  // namespace vorocrust
