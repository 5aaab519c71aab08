#include "geometry/triangle_shape.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vorocrust::geometry {

TriangleShape triangle_shape(const Point& a, const Point& b, const Point& c) {
  TriangleShape shape;
  const Point corners[3] = {a, b, c};
  for (int k = 0; k < 3; ++k) {
    const Point u = corners[(k + 1) % 3] - corners[k], v = corners[(k + 2) % 3] - corners[k];
    const double dot = u.dot(v);
    // atan2 stays accurate for angles near 0 and 180 degrees, where acos of a rounded cosine
    // does not, and gives 0 rather than NaN when an edge has zero length.
    shape.angles_degrees[k] = std::atan2(u.cross(v).norm(), dot) * (180.0 / std::numbers::pi);
    shape.obtuse[k] = dot < 0;
  }
  const double area = 0.5 * (b - a).cross(c - a).norm();
  const double ab = (b - a).norm(), bc = (c - b).norm(), ca = (a - c).norm();
  const double longest = std::max({ab, bc, ca});
  const double half_perimeter = 0.5 * (ab + bc + ca);
  if (area > 0 && longest > 0) {
    // Equals 2 sqrt(3) r / h (r the inradius), at most 1; the clamp only absorbs rounding.
    shape.quality = std::min(1.0, 6 * area / (std::numbers::sqrt3 * longest * half_perimeter));
  }
  return shape;
}

}  // namespace vorocrust::geometry
