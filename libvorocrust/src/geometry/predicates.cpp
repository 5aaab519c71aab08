// Exact predicates by a floating-point filter backed by exact expansion arithmetic.
//
// Fast path: evaluate the determinant in doubles and bound its rounding error from above by a
// multiple of its "permanent" (the same polynomial with every monomial made nonnegative). When
// the computed value exceeds that bound its sign is certainly right. Otherwise, which only
// happens for (nearly) degenerate inputs, the determinant is summed again exactly as a
// floating-point expansion: a list of doubles whose exact sum is the value.
#include "geometry/predicates.hpp"

#include <cassert>
#include <cmath>

namespace vorocrust::geometry {
namespace {

// Unit roundoff u: a correctly rounded operation has relative error at most u.
constexpr double kU = 0x1p-53;

// x + y == sum + error exactly (Knuth's TwoSum): the rounding error of an addition is itself
// a double and can be recovered without branching on which operand is larger.
inline void two_sum(double x, double y, double& sum, double& error) {
  sum = x + y;
  const double y_part = sum - x;
  const double x_part = sum - y_part;
  error = (x - x_part) + (y - y_part);
}

// x * y == product + error exactly: a fused multiply-add rounds only once, so it returns the
// low half of the exact product.
inline void two_product(double x, double y, double& product, double& error) {
  product = x * y;
  error = std::fma(x, y, -product);
}

// A coordinate difference b - a held exactly as hi + lo; the filter only had hi.
struct ExactDifference {
  double part[2];
  ExactDifference(double b, double a) { two_sum(b, -a, part[0], part[1]); }
};

// An exact running sum kept as a nonoverlapping expansion: components in increasing order of
// magnitude whose significant bits do not overlap, so the largest one alone has the sum's sign.
template <int Capacity>
class ExactSum {
 public:
  // Shewchuk's GROW-EXPANSION: propagating the new term upward through the components with
  // TwoSum keeps the expansion nonoverlapping and lengthens it by at most one. Dropping zero
  // errors is what keeps it short when the terms of a degenerate determinant cancel.
  void add(double term) {
    if (term == 0) return;
    int kept = 0;
    for (int i = 0; i < size_; ++i) {
      double error;
      two_sum(term, component_[i], term, error);
      if (error != 0) component_[kept++] = error;
    }
    assert(kept < Capacity);
    if (term != 0) component_[kept++] = term;
    size_ = kept;
  }

  // x * y * z added exactly: the product of two doubles is two doubles, each times z two more.
  void add_product(double sign, double x, double y, double z) {
    if (x == 0 || y == 0 || z == 0) return;
    double high, low;
    two_product(x, y, high, low);
    double p, e;
    two_product(high, z, p, e);
    add(sign * p);
    add(sign * e);
    two_product(low, z, p, e);
    add(sign * p);
    add(sign * e);
  }

  void add_product(double sign, double x, double y) {
    if (x == 0 || y == 0) return;
    double p, e;
    two_product(x, y, p, e);
    add(sign * p);
    add(sign * e);
  }

  int sign() const { return size_ == 0 ? 0 : (component_[size_ - 1] > 0 ? 1 : -1); }

 private:
  double component_[Capacity];
  int size_ = 0;
};

int orient2d_exact(double ax, double ay, double bx, double by, double cx, double cy) {
  const ExactDifference ux(bx, ax), uy(by, ay), vx(cx, ax), vy(cy, ay);
  // 2 monomials x 4 part combinations x 2 doubles per product.
  ExactSum<16> det;
  for (double p : ux.part)
    for (double q : vy.part) det.add_product(+1, p, q);
  for (double p : uy.part)
    for (double q : vx.part) det.add_product(-1, p, q);
  return det.sign();
}

int orient3d_exact(const Point& a, const Point& b, const Point& c, const Point& d) {
  const ExactDifference u[3] = {{b.x(), a.x()}, {b.y(), a.y()}, {b.z(), a.z()}};
  const ExactDifference v[3] = {{c.x(), a.x()}, {c.y(), a.y()}, {c.z(), a.z()}};
  const ExactDifference w[3] = {{d.x(), a.x()}, {d.y(), a.y()}, {d.z(), a.z()}};
  // det[u; v; w] by the Leibniz formula: one monomial u_i v_j w_k per permutation (i, j, k).
  struct Permutation {
    int i, j, k;
    double sign;
  };
  constexpr Permutation kPermutations[6] = {{0, 1, 2, +1}, {1, 2, 0, +1}, {2, 0, 1, +1},
                                            {0, 2, 1, -1}, {2, 1, 0, -1}, {1, 0, 2, -1}};
  // 6 monomials x 8 part combinations x 4 doubles per triple product.
  ExactSum<192> det;
  for (const Permutation& p : kPermutations)
    for (double x : u[p.i].part)
      for (double y : v[p.j].part)
        for (double z : w[p.k].part) det.add_product(p.sign, x, y, z);
  return det.sign();
}

}  // namespace

int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  const double ux = bx - ax, uy = by - ay, vx = cx - ax, vy = cy - ay;
  const double left = ux * vy, right = uy * vx;
  const double det = left - right;
  const double permanent = std::abs(left) + std::abs(right);
  // Each monomial goes through at most 4 roundings (two differences, the product, the final
  // subtraction), so |error| <= ((1+u)^4 - 1) * exact permanent < 4.0001u * permanent. The fifth
  // u covers the roundings made while computing the permanent and the bound themselves.
  const double bound = 5 * kU * permanent;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  // Every monomial has an exactly zero factor (a difference of equal doubles is exactly 0).
  if (permanent == 0) return 0;
  return orient2d_exact(ax, ay, bx, by, cx, cy);
}

int orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double ux = b.x() - a.x(), uy = b.y() - a.y(), uz = b.z() - a.z();
  const double vx = c.x() - a.x(), vy = c.y() - a.y(), vz = c.z() - a.z();
  const double wx = d.x() - a.x(), wy = d.y() - a.y(), wz = d.z() - a.z();
  const double vywz = vy * wz, vzwy = vz * wy;
  const double vzwx = vz * wx, vxwz = vx * wz;
  const double vxwy = vx * wy, vywx = vy * wx;
  const double det = ux * (vywz - vzwy) + uy * (vzwx - vxwz) + uz * (vxwy - vywx);
  const double permanent = std::abs(ux) * (std::abs(vywz) + std::abs(vzwy)) +
                           std::abs(uy) * (std::abs(vzwx) + std::abs(vxwz)) +
                           std::abs(uz) * (std::abs(vxwy) + std::abs(vywx));
  // Each monomial goes through at most 8 roundings (three differences, two products, the minor's
  // subtraction, two of the three additions); the ninth u covers computing the bound itself.
  const double bound = 9 * kU * permanent;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  // Every monomial has an exactly zero factor: common for axis-aligned faces.
  if (permanent == 0) return 0;
  return orient3d_exact(a, b, c, d);
}

}  // namespace vorocrust::geometry
