// The two spheres of the aspect ratio by brute force, for the tests: the smallest of the spheres
// through two to four of the points that encloses them all, the largest of the balls touching
// four of the planes that fits them all. Slow (fourth power of the count), independent of the
// library's algorithms.
#pragma once

#include <Eigen/Dense>
#include <limits>
#include <optional>
#include <vector>

#include "geometry/spheres.hpp"

namespace vorocrust::geometry {

// The sphere through `support` with its centre in their affine hull, if they are independent.
inline std::optional<Sphere> sphere_through(const std::vector<Point>& support) {
  const std::size_t k = support.size() - 1;
  Eigen::MatrixXd v(3, k);
  Eigen::VectorXd rhs(k);
  for (std::size_t i = 0; i < k; ++i) {
    v.col(static_cast<Eigen::Index>(i)) = support[i + 1] - support[0];
    rhs(static_cast<Eigen::Index>(i)) = 0.5 * v.col(static_cast<Eigen::Index>(i)).squaredNorm();
  }
  const Eigen::MatrixXd gram = v.transpose() * v;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(gram);
  lu.setThreshold(1e-10);
  if (!lu.isInvertible()) return std::nullopt;
  const Point centre = support[0] + v * lu.solve(rhs);
  return Sphere{centre, (support[0] - centre).norm()};
}

inline double brute_force_enclosing_radius(const std::vector<Point>& points) {
  double best = std::numeric_limits<double>::infinity();
  const std::size_t n = points.size();
  const auto consider = [&](const std::vector<Point>& support) {
    const std::optional<Sphere> s = sphere_through(support);
    if (!s || s->radius >= best) return;
    for (const Point& p : points)
      if ((p - s->centre).norm() > s->radius * (1 + 1e-12)) return;
    best = s->radius;
  };
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      consider({points[a], points[b]});
      for (std::size_t c = b + 1; c < n; ++c) {
        consider({points[a], points[b], points[c]});
        for (std::size_t d = c + 1; d < n; ++d) consider({points[a], points[b], points[c], points[d]});
      }
    }
  return best;
}

inline double brute_force_inscribed_radius(const std::vector<Plane>& planes) {
  double best = 0;
  const std::size_t n = planes.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      for (std::size_t c = b + 1; c < n; ++c)
        for (std::size_t d = c + 1; d < n; ++d) {
          Eigen::Matrix4d m;
          Eigen::Vector4d rhs;
          int row = 0;
          for (std::size_t i : {a, b, c, d}) {
            m.row(row) << planes[i].normal.transpose(), 1.0;
            rhs(row++) = planes[i].offset;
          }
          Eigen::FullPivLU<Eigen::Matrix4d> lu(m);
          if (!lu.isInvertible()) continue;
          const Eigen::Vector4d x = lu.solve(rhs);
          const Point centre = x.head<3>();
          bool inside = x(3) > best;
          for (const Plane& p : planes) inside = inside && p.normal.dot(centre) + x(3) <= p.offset + 1e-12;
          if (inside) best = x(3);
        }
  return best;
}

}  // namespace vorocrust::geometry
