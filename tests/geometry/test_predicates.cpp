// Exactness of orient2d/orient3d on inputs where plain floating point gets the sign wrong,
// checked against an independent exact oracle (128-bit integer determinants on lattice points).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>

#include "geometry/predicates.hpp"

namespace vorocrust::geometry {
namespace {

using Int = std::int64_t;
__extension__ typedef __int128 Wide;  // a GCC/Clang extension, exact for these oracles
using IntVec = std::array<Int, 3>;

int sign(Wide x) { return (x > 0) - (x < 0); }
int sign(double x) { return (x > 0) - (x < 0); }

int naive_orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  return sign((bx - ax) * (cy - ay) - (by - ay) * (cx - ax));
}

int naive_orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Point u = b - a, v = c - a, w = d - a;
  return sign(u.x() * (v.y() * w.z() - v.z() * w.y()) + u.y() * (v.z() * w.x() - v.x() * w.z()) +
              u.z() * (v.x() * w.y() - v.y() * w.x()));
}

// Points base + offset * unit for integer offsets: when unit is a multiple of every base
// coordinate's ulp and offsets stay small, the sum is exact, so the points sit on an exact
// lattice whose orientations an integer determinant decides.
struct Lattice {
  Point base;
  double unit;

  Point at(const IntVec& offset) const {
    Point p;
    for (int k = 0; k < 3; ++k) {
      p[k] = base[k] + static_cast<double>(offset[k]) * unit;
      // Sterbenz: p[k] - base[k] is exact, so this checks that p[k] is the lattice point.
      EXPECT_EQ(p[k] - base[k], static_cast<double>(offset[k]) * unit) << "lattice not exact";
    }
    return p;
  }
};

// Base points with "ugly" coordinates (no short binary expansion), and a unit that is a
// multiple of their ulps.
const Lattice kLattices[] = {
    {Point(0.1, 0.2, 0.3), 0x1p-54},
    {Point(12345.678, -9876.54321, 1000.0 / 3.0), 0x1p-39},
    {Point(-0.7, 0.3333333333333333, 0.9), 0x1p-53},
};

int exact_orient3d(const IntVec& a, const IntVec& b, const IntVec& c, const IntVec& d) {
  Wide u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) u[k] = b[k] - a[k], v[k] = c[k] - a[k], w[k] = d[k] - a[k];
  return sign(u[0] * (v[1] * w[2] - v[2] * w[1]) + u[1] * (v[2] * w[0] - v[0] * w[2]) +
              u[2] * (v[0] * w[1] - v[1] * w[0]));
}

int exact_orient2d(const IntVec& a, const IntVec& b, const IntVec& c) {
  const Wide ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
  return sign(ux * vy - uy * vx);
}

IntVec add(const IntVec& a, const IntVec& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
IntVec scale(Int s, const IntVec& a) { return {s * a[0], s * a[1], s * a[2]}; }

class LatticeCases : public ::testing::Test {
 protected:
  std::mt19937_64 rng{20240611};
  Int big() { return std::uniform_int_distribution<Int>(-(Int{1} << 30), Int{1} << 30)(rng); }
  Int small(Int r) { return std::uniform_int_distribution<Int>(-r, r)(rng); }
  IntVec big_vector() { return {big(), big(), big()}; }
  IntVec small_vector(Int r) { return {small(r), small(r), small(r)}; }
};

TEST(Orient, Conventions) {
  const Point o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  EXPECT_EQ(orient3d(o, x, y, z), 1);  // (x - o) x (y - o) points to +z
  EXPECT_EQ(orient3d(o, x, y, -z), -1);
  EXPECT_EQ(orient3d(o, x, y, Point(5, -7, 0)), 0);
  EXPECT_EQ(orient3d(o, o, y, z), 0);
  EXPECT_EQ(orient2d(0, 0, 1, 0, 0, 1), 1);  // counter-clockwise
  EXPECT_EQ(orient2d(0, 0, 0, 1, 1, 0), -1);
  EXPECT_EQ(orient2d(0, 0, 1, 1, 3, 3), 0);
  EXPECT_EQ(orient2d(2, 2, 2, 2, 3, 5), 0);
}

// The classic failure of floating-point orientation: near (0.5, 0.5), on the line y = x through
// (12, 12) and (24, 24). The exact determinant is 12 * (dy - dx) for a = (0.5 + dx, 0.5 + dy).
TEST(Orient2d, ClassicGridNearOneHalf) {
  int naive_wrong = 0;
  for (int i = 0; i < 256; ++i)
    for (int j = 0; j < 256; ++j) {
      const double ax = 0.5 + i * 0x1p-53, ay = 0.5 + j * 0x1p-53;
      const int expected = (j > i) - (j < i);
      ASSERT_EQ(orient2d(ax, ay, 12, 12, 24, 24), expected) << i << " " << j;
      ASSERT_EQ(orient2d(12, 12, 24, 24, ax, ay), expected) << i << " " << j;
      naive_wrong += naive_orient2d(ax, ay, 12, 12, 24, 24) != expected;
    }
  EXPECT_GT(naive_wrong, 1000) << "the grid no longer defeats plain floating point";
}

// Collinear points a + t (b - a), t an exactly representable integer, on ugly-coordinate lattices.
// (The differences are exact here, so plain floating point happens to get 0 as well; the points
// one lattice step off the line are where it must be exact.)
TEST_F(LatticeCases, Orient2dCollinearAndOneUnitOff) {
  for (const Lattice& lattice : kLattices)
    for (int trial = 0; trial < 3000; ++trial) {
      const IntVec ia{0, 0, 0}, ib = big_vector();
      const IntVec ic = scale(small(4), ib);
      const Point a = lattice.at(ia), b = lattice.at(ib), c = lattice.at(ic);
      ASSERT_EQ(orient2d(a.x(), a.y(), b.x(), b.y(), c.x(), c.y()), 0);
      ASSERT_EQ(orient2d(c.x(), c.y(), a.x(), a.y(), b.x(), b.y()), 0);
      const IntVec id = add(ic, small_vector(1));
      const Point d = lattice.at(id);
      ASSERT_EQ(orient2d(a.x(), a.y(), b.x(), b.y(), d.x(), d.y()), exact_orient2d(ia, ib, id));
    }
}

// Points (x, k x) of wildly different magnitudes on a line of small-integer slope: the
// differences are not representable, and plain floating point reports noise. A point one ulp
// above the line at x has exact orientation sign((c.x - b.x) * ulp) against b -> c.
TEST(Orient2d, CollinearPointsWithInexactDifferences) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<std::int64_t> significand(-(std::int64_t{1} << 40),
                                                          std::int64_t{1} << 40);
  std::uniform_int_distribution<int> exponent(-80, 40);
  auto wild = [&] { return std::ldexp(static_cast<double>(significand(rng)), exponent(rng)); };
  int naive_nonzero = 0, naive_wrong = 0;
  for (int trial = 0; trial < 30000; ++trial) {
    const double slope = trial % 3 == 0 ? 3 : trial % 3 == 1 ? -5 : 0.375;  // k x stays exact
    const double bx = wild(), cx = wild(), px = wild();
    const double by = slope * bx, cy = slope * cx, py = slope * px;
    ASSERT_EQ(orient2d(bx, by, cx, cy, px, py), 0);
    ASSERT_EQ(orient2d(px, py, cx, cy, bx, by), 0);
    naive_nonzero += naive_orient2d(bx, by, cx, cy, px, py) != 0;
    if (bx == cx) continue;
    const double above = std::nextafter(py, HUGE_VAL);
    const int expected = cx > bx ? 1 : -1;
    ASSERT_EQ(orient2d(bx, by, cx, cy, px, above), expected);
    ASSERT_EQ(orient2d(px, above, bx, by, cx, cy), expected);
    naive_wrong += naive_orient2d(bx, by, cx, cy, px, above) != expected;
  }
  EXPECT_GT(naive_nonzero, 1000);
  EXPECT_GT(naive_wrong, 1000);
}

// Coplanar points a, a + u, a + v, a + s u + t v with 30-bit u, v: the products of differences
// have 60 significant bits, so the plain determinant is rounding noise, yet exactly 0.
TEST_F(LatticeCases, Orient3dCoplanarAndOneUnitOff) {
  int naive_nonzero = 0, naive_wrong = 0;
  for (const Lattice& lattice : kLattices)
    for (int trial = 0; trial < 3000; ++trial) {
      const IntVec ia = small_vector(1000), iu = big_vector(), iv = big_vector();
      const IntVec ib = add(ia, iu), ic = add(ia, iv);
      const IntVec id = add(ia, add(scale(small(3), iu), scale(small(3), iv)));
      const Point a = lattice.at(ia), b = lattice.at(ib), c = lattice.at(ic), d = lattice.at(id);
      ASSERT_EQ(orient3d(a, b, c, d), 0);
      naive_nonzero += naive_orient3d(a, b, c, d) != 0;
      const IntVec ie = add(id, small_vector(2));
      const Point e = lattice.at(ie);
      const int expected = exact_orient3d(ia, ib, ic, ie);
      ASSERT_EQ(orient3d(a, b, c, e), expected);
      ASSERT_EQ(orient3d(e, c, b, a), expected);  // two swaps
      naive_wrong += naive_orient3d(a, b, c, e) != expected;
    }
  EXPECT_GT(naive_nonzero, 1000);
  EXPECT_GT(naive_wrong, 0);
}

// All 4! (resp. 3!) argument orders change which point the differences are taken from, hence
// every rounding on the way; the signs must still follow the permutation's parity.
TEST_F(LatticeCases, SignFollowsPermutationParity) {
  for (const Lattice& lattice : kLattices)
    for (int trial = 0; trial < 300; ++trial) {
      const IntVec iu = big_vector(), iv = big_vector();
      const IntVec ip[4] = {
          {0, 0, 0}, iu, iv, add(add(scale(small(3), iu), scale(small(3), iv)), small_vector(1))};
      const Point p[4] = {lattice.at(ip[0]), lattice.at(ip[1]), lattice.at(ip[2]),
                          lattice.at(ip[3])};
      const int reference = exact_orient3d(ip[0], ip[1], ip[2], ip[3]);
      std::array<int, 4> order = {0, 1, 2, 3};
      do {
        int inversions = 0;
        for (int i = 0; i < 4; ++i)
          for (int j = i + 1; j < 4; ++j) inversions += order[i] > order[j];
        const int parity = inversions % 2 == 0 ? 1 : -1;
        ASSERT_EQ(orient3d(p[order[0]], p[order[1]], p[order[2]], p[order[3]]), parity * reference);
      } while (std::next_permutation(order.begin(), order.end()));

      std::array<int, 3> order2 = {0, 1, 2};
      const int reference2 = exact_orient2d(ip[0], ip[1], ip[3]);
      const Point q[3] = {p[0], p[1], p[3]};
      do {
        int inversions = 0;
        for (int i = 0; i < 3; ++i)
          for (int j = i + 1; j < 3; ++j) inversions += order2[i] > order2[j];
        const int parity = inversions % 2 == 0 ? 1 : -1;
        const Point &a = q[order2[0]], &b = q[order2[1]], &c = q[order2[2]];
        ASSERT_EQ(orient2d(a.x(), a.y(), b.x(), b.y(), c.x(), c.y()), parity * reference2);
      } while (std::next_permutation(order2.begin(), order2.end()));
    }
}

// Scaling by a power of two is exact, so it cannot change any sign (within the documented range).
TEST_F(LatticeCases, InvariantUnderPowerOfTwoScaling) {
  for (const Lattice& lattice : kLattices)
    for (int trial = 0; trial < 500; ++trial) {
      const IntVec iu = big_vector(), iv = big_vector();
      const IntVec id = add(add(scale(small(3), iu), scale(small(3), iv)), small_vector(1));
      const Point a = lattice.at({0, 0, 0}), b = lattice.at(iu), c = lattice.at(iv),
                  d = lattice.at(id);
      const int expected = exact_orient3d({0, 0, 0}, iu, iv, id);
      for (double factor : {0x1p150, 0x1p-150, 0x1p-1})
        ASSERT_EQ(orient3d(a * factor, b * factor, c * factor, d * factor), expected) << factor;
    }
}

// Differences that are not representable (points of wildly different magnitudes) exercise the
// low halves of the exact differences. Points with z == x (or y == x) are exactly coplanar
// (collinear); the exact sign of a point just off the line y = x is known by construction.
TEST(Orient, InexactDifferencesOnExactlyDegenerateInputs) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-150, 150);
  auto wild = [&] { return std::ldexp(mantissa(rng), exponent(rng)); };
  for (int trial = 0; trial < 20000; ++trial) {
    Point p[4];
    for (Point& q : p) {
      q = Point(wild(), wild(), 0);
      q.z() = trial % 2 ? q.x() : -q.y();
    }
    ASSERT_EQ(orient3d(p[0], p[1], p[2], p[3]), 0);
    ASSERT_EQ(orient2d(p[0].x(), p[0].x(), p[1].x(), p[1].x(), p[2].y(), p[2].y()), 0);
  }
  // b and c on y = x; a just below it (x > y), so a is right of the directed line b -> c.
  const double ax = 1 + 0x1p-52, ay = 1, b = -0x1p60, c = 0x1p60;
  EXPECT_EQ(naive_orient2d(b, b, c, c, ax, ay), 0);  // the plain evaluation rounds it away
  EXPECT_EQ(orient2d(b, b, c, c, ax, ay), -1);
  EXPECT_EQ(orient2d(b, b, c, c, ay, ax), 1);
  EXPECT_EQ(orient3d(Point(b, b, 0), Point(c, c, 0), Point(0, 0, 1), Point(ax, ay, 0.5)), 1);
}

// On well-conditioned inputs, where rounding cannot flip the sign, the exact predicates agree
// with the plain formula.
TEST(Orient, AgreesWithPlainFormulaWhenWellConditioned) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  auto point = [&] { return Point(coordinate(rng), coordinate(rng), coordinate(rng)); };
  int compared = 0;
  for (int trial = 0; trial < 100000; ++trial) {
    const Point a = point(), b = point(), c = point(), d = point();
    const double det3 = (b - a).dot((c - a).cross(d - a));
    if (std::abs(det3) > 1e-9) {
      ASSERT_EQ(orient3d(a, b, c, d), sign(det3));
      ++compared;
    }
    const double det2 = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    if (std::abs(det2) > 1e-9) {
      ASSERT_EQ(orient2d(a.x(), a.y(), b.x(), b.y(), c.x(), c.y()), sign(det2));
    }
  }
  EXPECT_GT(compared, 99000);
}

}  // namespace
}  // namespace vorocrust::geometry
