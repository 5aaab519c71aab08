#include "geometry/closest_point.hpp"

#include <algorithm>
#include <iterator>

namespace vorocrust::geometry {

Point closest_on_segment(const Point& p, const Point& a, const Point& b) {
  const Point ab = b - a;
  const double length2 = ab.squaredNorm();
  if (length2 == 0) return a;
  const double t = std::clamp((p - a).dot(ab) / length2, 0.0, 1.0);
  return a + t * ab;
}

// By regions of the triangle's plane: the corner, edge or interior whose Voronoi region holds p.
Point closest_on_triangle(const Point& p, const Point& a, const Point& b, const Point& c) {
  const Point ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Point bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Point cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = va + vb + vc;
  if (!(denom > 0)) {  // degenerate triangle: nearest of its edges
    const Point candidates[3] = {closest_on_segment(p, a, b), closest_on_segment(p, b, c), closest_on_segment(p, c, a)};
    return *std::min_element(std::begin(candidates), std::end(candidates),
                             [&](const Point& x, const Point& y) { return (x - p).squaredNorm() < (y - p).squaredNorm(); });
  }
  return a + (vb / denom) * ab + (vc / denom) * ac;
}

double distance_to_segment(const Point& p, const Point& a, const Point& b) { return (closest_on_segment(p, a, b) - p).norm(); }

double distance_to_triangle(const Point& p, const Point& a, const Point& b, const Point& c) {
  return (closest_on_triangle(p, a, b, c) - p).norm();
}

}  // namespace vorocrust::geometry
