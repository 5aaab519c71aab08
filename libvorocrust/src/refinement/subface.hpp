// Internal: the pieces of input elements that maximal Poisson-disk sampling works on (paper 2.3,
// "Sampling Basics"): a segment of a crease edge, or a triangle inside a patch face. Splitting
// halves a segment and cuts a triangle into four of equal area.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "geometry/closest_point.hpp"
#include "geometry/surface_sampling.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

class Subface {
 public:
  static Subface segment(const Point& a, const Point& b, Index edge) { return Subface({a, b, b}, 2, edge); }
  static Subface triangle(const Point& a, const Point& b, const Point& c, Index face) { return Subface({a, b, c}, 3, face); }

  bool is_segment() const { return corners_ == 2; }
  int corner_count() const { return corners_; }
  const Point& corner(int k) const { return p_[k]; }
  Index element;         // the crease edge or patch face the piece lies on
  bool focused = false;  // sampled only where it meets a region some ball gave up

  double measure() const {
    return is_segment() ? (p_[1] - p_[0]).norm() : 0.5 * (p_[1] - p_[0]).cross(p_[2] - p_[0]).norm();
  }
  Point centroid() const { return is_segment() ? Point(0.5 * (p_[0] + p_[1])) : Point((p_[0] + p_[1] + p_[2]) / 3); }
  double circumradius(const Point& centre) const {
    double r = 0;
    for (int k = 0; k < corners_; ++k) r = std::max(r, (p_[k] - centre).norm());
    return r;
  }
  Point closest_point(const Point& q) const {
    return is_segment() ? geometry::closest_on_segment(q, p_[0], p_[1])
                        : geometry::closest_on_triangle(q, p_[0], p_[1], p_[2]);
  }
  Point random_point(std::mt19937_64& rng, std::uniform_real_distribution<double>& unit) const {
    const double u = unit(rng);
    if (is_segment()) return p_[0] + u * (p_[1] - p_[0]);
    const double v = unit(rng);
    return geometry::point_in_triangle(p_[0], p_[1], p_[2], u, v);
  }
  // Two halves of a segment, four quarters of a triangle (the unused slots are segments of zero
  // measure, which callers skip). A triangle is quartered by halving its longest edge and then each
  // half's: cutting through the edge midpoints instead would keep a sliver of a face a sliver at
  // every level, and a long piece meets more balls and straddles the rim of their union more
  // often (on netgen_hinge, whose faces are mostly slivers, the pool held twice the pieces).
  std::array<Subface, 4> split() const {
    std::array<Subface, 4> children = [&]() -> std::array<Subface, 4> {
      if (is_segment()) {
        const Point m = 0.5 * (p_[0] + p_[1]);
        return {segment(p_[0], m, element), segment(m, p_[1], element), segment(m, m, element), segment(m, m, element)};
      }
      const auto [first, second] = bisected();
      const auto [a, b] = first.bisected();
      const auto [c, d] = second.bisected();
      return {a, b, c, d};
    }();
    for (Subface& c : children) c.focused = focused;
    return children;
  }

 private:
  Subface(std::array<Point, 3> p, int corners, Index e) : element(e), p_(p), corners_(corners) {}
  // The two halves of a triangle across the midpoint of its longest edge, oriented as it is.
  std::array<Subface, 2> bisected() const {
    int longest = 0;
    for (int k = 1; k < 3; ++k) {
      if ((p_[(k + 1) % 3] - p_[k]).squaredNorm() > (p_[(longest + 1) % 3] - p_[longest]).squaredNorm()) longest = k;
    }
    const Point& a = p_[longest];
    const Point& b = p_[(longest + 1) % 3];
    const Point& c = p_[(longest + 2) % 3];
    const Point m = 0.5 * (a + b);
    return {triangle(a, m, c, element), triangle(m, b, c, element)};
  }

  std::array<Point, 3> p_;
  int corners_;
};

}  // namespace vorocrust
