#include "seeds/sphere_triplet.hpp"

#include <cmath>

namespace vorocrust {

// In the frame of the triangle: the radical line of the three spheres is perpendicular to the
// plane of the centres and passes through their power centre; the points sit on it at the
// height that puts them on the first sphere.
std::optional<std::array<Point, 2>> sphere_triplet_points(const Point& c0, double r0, const Point& c1, double r1,
                                                           const Point& c2, double r2) {
  const Point u = c1 - c0, v = c2 - c0;
  const Point n = u.cross(v);
  const double n2 = n.squaredNorm();
  if (!(n2 > 1e-24 * u.squaredNorm() * v.squaredNorm())) return std::nullopt;  // collinear centres
  // Power centre h = c0 + a u + b v with |h - c_k|^2 - r_k^2 equal for all k:
  //   2 u.(h - c0) = |u|^2 + r0^2 - r1^2,  2 v.(h - c0) = |v|^2 + r0^2 - r2^2.
  const double ru = 0.5 * (u.squaredNorm() + r0 * r0 - r1 * r1);
  const double rv = 0.5 * (v.squaredNorm() + r0 * r0 - r2 * r2);
  // Closed form of the 2x2 solve: h - c0 = (ru (v x n) + rv (n x u)) / |n|^2.
  const Point offset = (ru * v.cross(n) + rv * n.cross(u)) / n2;
  const double height2 = r0 * r0 - offset.squaredNorm();
  if (!(height2 > 0)) return std::nullopt;
  const Point h = c0 + offset;
  const Point up = n * std::sqrt(height2 / n2);
  return std::array<Point, 2>{h + up, h - up};
}

}  // namespace vorocrust
