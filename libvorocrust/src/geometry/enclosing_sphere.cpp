// Welzl's smallest enclosing sphere with the move-to-front heuristic. The support spheres are
// built one point at a time (each new centre moves from the last one along the new point's
// direction orthogonal to the support so far), as Gärtner's construction does, which needs no
// linear solve and tells affinely dependent points apart.
#include <algorithm>
#include <array>
#include <cmath>

#include "geometry/fixed_shuffle.hpp"
#include "geometry/spheres.hpp"

namespace vorocrust::geometry {

namespace {

// A direction shorter than this, relative to the support so far, adds no dimension to it.
constexpr double kDependent = 1e-20;  // squared
// A point this much beyond the sphere, relative to its squared radius, is inside.
constexpr double kInside = 1e-12;

class Welzl {
 public:
  explicit Welzl(std::vector<Point>& points) : points_(points) {}

  Sphere run() {
    support_ = 0;
    squared_radius_ = -1;
    grow(points_.size());
    return {centre_, 0};
  }

 private:
  // The smallest sphere holding the first `end` points with the support on its boundary.
  void grow(std::size_t end) {
    if (support_ == 4) return;
    for (std::size_t i = 0; i < end; ++i) {
      if ((points_[i] - centre_).squaredNorm() <= squared_radius_ * (1 + kInside)) continue;
      if (!push(points_[i])) continue;
      grow(i);
      --support_;
      std::rotate(points_.begin(), points_.begin() + static_cast<std::ptrdiff_t>(i),
                  points_.begin() + static_cast<std::ptrdiff_t>(i) + 1);
    }
  }

  // The sphere with the support and p on its boundary, centred in their affine hull; false
  // (and nothing changed) when p adds no dimension to the support.
  bool push(const Point& p) {
    if (support_ == 0) {
      first_ = p;
      centres_[0] = centre_ = p;
      squared_radii_[0] = squared_radius_ = 0;
      support_ = 1;
      return true;
    }
    const Point v = p - first_;
    Point w = v;
    for (int k = 0; k + 1 < support_; ++k) w -= (w.dot(directions_[k]) / lengths_[k]) * directions_[k];
    const double z = w.squaredNorm();
    const double base = squared_radii_[support_ - 1];
    if (!(z > kDependent * std::max(base, v.squaredNorm()))) return false;
    const double t = ((p - centres_[support_ - 1]).squaredNorm() - base) / (2 * z);
    directions_[support_ - 1] = w;
    lengths_[support_ - 1] = z;
    centres_[support_] = centre_ = centres_[support_ - 1] + t * w;
    squared_radii_[support_] = squared_radius_ = base + t * t * z;
    ++support_;
    return true;
  }

  std::vector<Point>& points_;
  int support_ = 0;
  Point first_ = Point::Zero();
  std::array<Point, 3> directions_;
  std::array<double, 3> lengths_{};
  std::array<Point, 5> centres_;  // of the support's first k points' sphere
  std::array<double, 5> squared_radii_{};
  Point centre_ = Point::Zero();  // the current sphere
  double squared_radius_ = -1;
};

}  // namespace

Sphere smallest_enclosing_sphere(std::vector<Point> points) {
  // In a frame of unit extent about the points' mean, where the tolerances are meant.
  Point mean = Point::Zero();
  for (const Point& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  double extent = 0;
  for (const Point& p : points) extent = std::max(extent, (p - mean).norm());
  if (extent == 0) return {points.front(), 0};
  for (Point& p : points) p = (p - mean) / extent;

  fixed_shuffle(points);
  Sphere s = Welzl(points).run();
  double farthest = 0;
  for (const Point& p : points) farthest = std::max(farthest, (p - s.centre).squaredNorm());
  return {mean + extent * s.centre, extent * std::sqrt(farthest)};
}

}  // namespace vorocrust::geometry
