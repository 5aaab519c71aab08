// Triangle-triangle tests: crafted configurations for every case, then random small-integer
// configurations (full of coplanarity and touching) against an independent separating-axis
// oracle in exact integer arithmetic, under all corner orders and both argument orders.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "geometry/triangle_intersection.hpp"

namespace vorocrust::geometry {
namespace {

using T = TriangleCorners;

Point P(double x, double y, double z) { return Point(x, y, z); }

// --- Faces without shared vertices: any contact counts. ---

const T kBase = {P(0, 0, 0), P(1, 0, 0), P(0, 1, 0)};

TEST(TrianglesIntersect, SeparatedTrianglesDoNot) {
  EXPECT_FALSE(triangles_intersect(kBase, {P(0, 0, 1), P(1, 0, 1), P(0, 1, 1)}));  // parallel
  EXPECT_FALSE(triangles_intersect(kBase, {P(5, 5, 5), P(6, 5, 5), P(5, 6, 7)}));
  // Crossing t's plane, but beyond its hypotenuse.
  EXPECT_FALSE(triangles_intersect(kBase, {P(0.6, 0.6, -1), P(0.7, 0.6, 1), P(0.6, 0.7, 1)}));
}

TEST(TrianglesIntersect, PiercingTriangles) {
  EXPECT_TRUE(triangles_intersect(kBase, {P(0.2, 0.2, -1), P(0.3, 0.2, 1), P(0.2, 0.3, 1)}));
  // A large triangle through the middle of a small one: no vertex of either inside the other.
  EXPECT_TRUE(triangles_intersect(kBase, {P(-5, 0.3, -1), P(5, 0.3, -1), P(0, 0.3, 3)}));
}

TEST(TrianglesIntersect, TouchingAtAPointCounts) {
  // A vertex on t's interior, and one ulp-scale step above it.
  EXPECT_TRUE(triangles_intersect(kBase, {P(0.25, 0.25, 0), P(0.25, 0.25, 1), P(1, 1, 1)}));
  EXPECT_FALSE(triangles_intersect(kBase, {P(0.25, 0.25, 0x1p-60), P(0.25, 0.25, 1), P(1, 1, 1)}));
  // Coincident vertices that are different mesh vertices.
  EXPECT_TRUE(triangles_intersect(kBase, {P(1, 0, 0), P(2, 0, 1), P(2, 1, 0)}));
  // A vertex on t's edge.
  EXPECT_TRUE(triangles_intersect(kBase, {P(0.5, 0, 0), P(0.5, -1, 1), P(0.5, -1, -1)}));
}

TEST(TrianglesIntersect, EdgeTouchingEdgeAcrossPlanes) {
  // u in the plane x = 0.5; its edge passes through (0.5, 0, 0) on t's edge y = 0.
  const T u = {P(0.5, -0.5, -0.5), P(0.5, 0.5, 0.5), P(0.5, -0.5, 1)};
  EXPECT_TRUE(triangles_intersect(kBase, u));
  const Point shift(0, -0x1p-40, 0);
  EXPECT_FALSE(triangles_intersect(kBase, {u[0] + shift, u[1] + shift, u[2] + shift}));
}

TEST(TrianglesIntersect, CoplanarTriangles) {
  EXPECT_TRUE(triangles_intersect(kBase, {P(0.2, 0.2, 0), P(2, 0.2, 0), P(0.2, 2, 0)}));
  EXPECT_FALSE(triangles_intersect(kBase, {P(1, 1, 0), P(2, 1, 0), P(1, 2, 0)}));
  // Contained either way round: no edges meet.
  const T small = {P(0.1, 0.1, 0), P(0.2, 0.1, 0), P(0.1, 0.2, 0)};
  EXPECT_TRUE(triangles_intersect(kBase, small));
  EXPECT_TRUE(triangles_intersect(small, kBase));
  // Star of David: edges cross, no vertex inside the other triangle.
  EXPECT_TRUE(triangles_intersect({P(0, 0, 0), P(4, 0, 0), P(2, 3, 0)},
                                  {P(0, 2, 0), P(4, 2, 0), P(2, -1, 0)}));
  // Overlapping collinear edges along x + y = 1, then moved just off that line.
  EXPECT_TRUE(triangles_intersect(kBase, {P(0.5, 0.5, 0), P(2, 2, 0), P(-1, 2, 0)}));
  const double e = 0x1p-50;
  EXPECT_FALSE(triangles_intersect(
      kBase, {P(0.5 + e, 0.5 + e, 0), P(2 + e, 2 + e, 0), P(-1 + e, 2 + e, 0)}));
  // In the tilted plane z = x + y.
  const T tilted = {P(0, 0, 0), P(1, 0, 1), P(0, 1, 1)};
  EXPECT_TRUE(
      triangles_intersect(tilted, {P(0.25, 0.25, 0.5), P(0.5, 0.25, 0.75), P(0.25, 0.5, 0.75)}));
  EXPECT_FALSE(triangles_intersect(tilted, {P(1, 1, 2), P(2, 1, 3), P(1, 2, 3)}));
}

// A vertex of u exactly on a tilted plane with ugly coordinates, where a floating-point plane
// test would be noise; one lattice step off the plane it touches or misses depending on the side.
TEST(TrianglesIntersect, TouchingOnAnUglyPlaneIsExact) {
  const Point base(0.1, 0.2, 0.3);
  const double unit = 0x1p-54;  // a multiple of the ulps of base's coordinates
  auto at = [&](double i, double j, double k) {
    const Point p = base + unit * Point(i, j, k);
    EXPECT_EQ(p - base, unit * Point(i, j, k));  // exact lattice point
    return p;
  };
  const Point U(4.0 * 123456789, 4.0 * -98765431, 4.0 * 55555557);
  const Point V(4.0 * -31415926, 4.0 * 27182818, 4.0 * 141421356);
  const Point W(300000007, 700000001, -200000003);
  const T t = {at(0, 0, 0), at(U.x(), U.y(), U.z()), at(V.x(), V.y(), V.z())};
  const Point m = (U + V) / 4;  // barycentric (1/2, 1/4, 1/4): inside t
  const Point q1 = m + W, q2 = m + W + U / 4;
  const Point p = at(m.x(), m.y(), m.z());
  const Point r1 = at(q1.x(), q1.y(), q1.z()), r2 = at(q2.x(), q2.y(), q2.z());
  EXPECT_TRUE(triangles_intersect(t, {p, r1, r2}));
  const bool above = triangles_intersect(t, {at(m.x(), m.y(), m.z() + 1), r1, r2});
  const bool below = triangles_intersect(t, {at(m.x(), m.y(), m.z() - 1), r1, r2});
  EXPECT_NE(above, below);
}

// --- Faces sharing one vertex v (corner 0 of both below). ---

const Point v(0, 0, 0);
const T kFan = {v, P(1, 0, 0), P(0, 1, 0)};
const SharedCorners kFirstCorners = {0, -1, -1};

bool improper_at_v(const T& u) { return improperly_intersect(kFan, u, kFirstCorners); }

TEST(SharedVertex, FacesMeetingOnlyAtTheVertex) {
  EXPECT_FALSE(improper_at_v({v, P(0, 0, 1), P(-1, -1, 0)}));  // other side of the crossing line
  EXPECT_FALSE(improper_at_v({v, P(-1, 0, 0), P(0, 0, 1)}));   // an edge in t's plane, outside
  EXPECT_FALSE(improper_at_v({v, P(1, 1, 1), P(-1, 2, 3)}));   // wholly above t's plane
}

TEST(SharedVertex, FacesCrossingBeyondTheVertex) {
  EXPECT_TRUE(improper_at_v({v, P(0.2, 0.2, 1), P(0.3, 0.3, -1)}));  // opposite edge pierces t
  EXPECT_TRUE(improper_at_v({v, P(0.5, 0.5, 1), P(0.5, 0.5, -1)}));  // through t's far edge
  EXPECT_TRUE(improper_at_v({v, P(0.5, 0, 0), P(0, 0, 1)}));         // along t's edge
  // u's unshared vertex at t's unshared vertex, but as a different mesh vertex.
  EXPECT_TRUE(improper_at_v({v, P(1, 0, 0), P(0, 0, 1)}));
  // t's opposite edge pierces u (u's opposite edge stays clear of t).
  EXPECT_TRUE(improper_at_v({v, P(2, 2, 1), P(2, 2, -1)}));
}

TEST(SharedVertex, CoplanarWedges) {
  EXPECT_FALSE(improper_at_v({v, P(-1, 0, 0), P(0, -1, 0)}));       // opposite quadrant
  EXPECT_FALSE(improper_at_v({v, P(0, -1, 0), P(1, -1, 0)}));       // adjacent, meeting only at v
  EXPECT_FALSE(improper_at_v({v, P(-1, 0, 0), P(-1, -1, 0)}));      // edges on opposite rays
  EXPECT_TRUE(improper_at_v({v, P(1, 1, 0), P(-1, 2, 0)}));         // overlapping wedges
  EXPECT_TRUE(improper_at_v({v, P(3, 0, 0), P(1, -1, 0)}));         // a common boundary ray
  EXPECT_TRUE(improper_at_v({v, P(0.2, 0.1, 0), P(0.1, 0.2, 0)}));  // u inside t
  EXPECT_TRUE(improper_at_v({v, P(-1, 3, 0), P(3, -1, 0)}));        // t inside u
}

// --- Faces sharing an edge ab. ---

TEST(SharedEdge, FoldedOnlyWhenCoplanarOnTheSameSide) {
  const Point a(0, 0, 0), b(1, 0, 0), p(0, 1, 0);
  const T t = {a, b, p};
  auto improper = [&](const Point& q) {
    // u lists the edge the other way round, as a consistently oriented neighbour would.
    return improperly_intersect(t, {b, a, q}, {1, 0, -1});
  };
  EXPECT_FALSE(improper(P(0.5, -1, 0)));       // flat continuation
  EXPECT_TRUE(improper(P(0.5, 1, 0)));         // folded back onto t
  EXPECT_TRUE(improper(P(7, 0.001, 0)));       // folded, even far beyond t
  EXPECT_FALSE(improper(P(0.5, 1, 0x1p-60)));  // almost folded
  EXPECT_FALSE(improper(P(0.5, 0, 1)));        // a dihedral angle
  // Folded in the tilted plane z = x + y; 0.1 + 0.1 is exact (a doubling), so the ugly third
  // corner lies exactly on that plane.
  const T tilted = {P(0, 0, 0), P(0.75, 0.5, 1.25), P(0.1, 0.1, 0.1 + 0.1)};
  EXPECT_TRUE(improperly_intersect(tilted, {P(0.25, 0.5, 0.75), tilted[0], tilted[1]}, {1, 2, -1}));
  EXPECT_FALSE(improperly_intersect(tilted, {P(0.5, 0, 0.5), tilted[0], tilted[1]}, {1, 2, -1}));
}

// --- Skipped configurations. ---

TEST(TriangleIntersection, DegenerateTrianglesNeverIntersect) {
  const T collinear = {P(0, 0, 0), P(0.5, 0.5, 0), P(1, 1, 0)};
  const T repeated = {P(0.2, 0.2, 0), P(0.2, 0.2, 0), P(1, 1, 1)};
  EXPECT_TRUE(is_degenerate(collinear));
  EXPECT_TRUE(is_degenerate(repeated));
  EXPECT_FALSE(is_degenerate(kBase));
  EXPECT_FALSE(triangles_intersect(kBase, collinear));
  EXPECT_FALSE(triangles_intersect(repeated, kBase));
  // Collinear with ugly coordinates (a + 3 (b - a), all exact), then one ulp off the line.
  const Point a(0.1, 0.2, 0.3), d(3 * 0x1p-52, -5 * 0x1p-52, 7 * 0x1p-52);
  EXPECT_TRUE(is_degenerate({a, a + d, a + 3 * d}));
  EXPECT_FALSE(is_degenerate({a, a + d, a + 3 * d + Point(0, 0, 0x1p-54)}));
}

TEST(TriangleIntersection, DuplicateFacesAreLeftToTheirOwnCheck) {
  EXPECT_FALSE(improperly_intersect(kBase, kBase, {0, 1, 2}));
  EXPECT_FALSE(improperly_intersect(kBase, {kBase[0], kBase[2], kBase[1]}, {0, 2, 1}));
}

TEST(TriangleIntersection, SharedCornersByIndex) {
  EXPECT_EQ(shared_corners({3, 5, 7}, {7, 9, 3}), (SharedCorners{2, -1, 0}));
  EXPECT_EQ(shared_corners({3, 5, 7}, {1, 2, 4}), kNoSharedCorners);
  EXPECT_EQ(shared_corners({3, 5, 7}, {5, 3, 8}), (SharedCorners{1, 0, -1}));
}

// --- Random small-integer configurations against a separating-axis oracle. ---

using IntVec = std::array<std::int64_t, 3>;

IntVec operator-(const IntVec& a, const IntVec& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
IntVec operator+(const IntVec& a, const IntVec& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
IntVec twice(const IntVec& a) { return {2 * a[0], 2 * a[1], 2 * a[2]}; }
std::int64_t dot(const IntVec& a, const IntVec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
IntVec cross(const IntVec& a, const IntVec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
bool is_zero(const IntVec& a) { return a == IntVec{0, 0, 0}; }

// Two closed convex planar polygons are disjoint iff their projections onto one of these axes
// are disjoint: the facet normals of their Minkowski difference are among the polygon normals,
// cross products of an edge of each, and (for parallel planes) normal-times-edge in-plane axes.
bool polygons_meet(const std::vector<IntVec>& p, const std::vector<IntVec>& q) {
  auto edges = [](const std::vector<IntVec>& poly) {
    std::vector<IntVec> e;
    for (std::size_t i = 0; i < poly.size(); ++i)
      e.push_back(poly[(i + 1) % poly.size()] - poly[i]);
    return e;
  };
  const std::vector<IntVec> ep = edges(p), eq = edges(q);
  const IntVec np = cross(ep[0], p[2] - p[0]), nq = cross(eq[0], q[2] - q[0]);
  std::vector<IntVec> axes = {np, nq};
  for (const IntVec& a : ep) {
    axes.push_back(cross(np, a));
    for (const IntVec& b : eq) axes.push_back(cross(a, b));
  }
  for (const IntVec& b : eq) axes.push_back(cross(nq, b));
  for (const IntVec& axis : axes) {
    if (is_zero(axis)) continue;
    auto range = [&](const std::vector<IntVec>& poly) {
      std::int64_t lo = dot(axis, poly[0]), hi = lo;
      for (const IntVec& x : poly) lo = std::min(lo, dot(axis, x)), hi = std::max(hi, dot(axis, x));
      return std::pair(lo, hi);
    };
    const auto [plo, phi] = range(p);
    const auto [qlo, qhi] = range(q);
    if (phi < qlo || qhi < plo) return false;
  }
  return true;
}

struct Case {
  std::vector<IntVec> points;
  Triangle t, u;  // indices into points
};

bool int_degenerate(const Case& c, const Triangle& f) {
  const auto& p = c.points;
  return is_zero(cross(p[f[1]] - p[f[0]], p[f[2]] - p[f[0]]));
}

// Independent oracle for improper intersection.
// No shared vertex: any contact. One shared vertex v: the triangles share more than v iff
// their wedges at v share a ray, iff the part of one triangle away from v (barycentric weight of
// v at most 1/2) meets the other triangle. A shared edge: coplanar with both far corners on the
// same side of it.
bool oracle(const Case& c) {
  const auto& p = c.points;
  const Triangle &t = c.t, &u = c.u;
  std::vector<std::pair<int, int>> shared;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (t[i] == u[j]) shared.emplace_back(i, j);
  if (shared.empty())
    return polygons_meet({p[t[0]], p[t[1]], p[t[2]]}, {p[u[0]], p[u[1]], p[u[2]]});
  if (shared.size() == 1) {
    const IntVec vv = p[t[shared[0].first]];
    auto far_part = [&](const Triangle& f, int corner) {  // doubled coordinates
      const IntVec a = p[f[(corner + 1) % 3]], b = p[f[(corner + 2) % 3]];
      return std::vector<IntVec>{vv + a, twice(a), twice(b), vv + b};
    };
    auto doubled = [&](const Triangle& f) {
      return std::vector<IntVec>{twice(p[f[0]]), twice(p[f[1]]), twice(p[f[2]])};
    };
    return polygons_meet(far_part(t, shared[0].first), doubled(u)) ||
           polygons_meet(far_part(u, shared[0].second), doubled(t));
  }
  const int tp = 3 - shared[0].first - shared[1].first,
            uq = 3 - shared[0].second - shared[1].second;
  const IntVec a = p[t[shared[0].first]], b = p[t[shared[1].first]];
  const IntVec nt = cross(b - a, p[t[tp]] - a), nu = cross(b - a, p[u[uq]] - a);
  return is_zero(cross(nt, nu)) && dot(nt, nu) > 0;
}

// improperly_intersect on the case, after permuting each face's corners and maybe swapping them.
bool evaluate(const Case& c, const std::array<int, 3>& tperm, const std::array<int, 3>& uperm,
              bool swap) {
  Triangle t = {c.t[tperm[0]], c.t[tperm[1]], c.t[tperm[2]]};
  Triangle u = {c.u[uperm[0]], c.u[uperm[1]], c.u[uperm[2]]};
  if (swap) std::swap(t, u);
  auto corners = [&](const Triangle& f) {
    T x;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) x[i][k] = static_cast<double>(c.points[f[i]][k]);
    return x;
  };
  return improperly_intersect(corners(t), corners(u), shared_corners(t, u));
}

// `shape` lists u's corners as indices into t's corners (0-2) or fresh points (3+).
void check_random_cases(int trials, int extent, const Triangle& shape, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::int64_t> coordinate(0, extent);
  int tested = 0, intersecting = 0, coplanar = 0;
  for (int trial = 0; trial < trials; ++trial) {
    Case c;
    // A third of the cases in the plane z = 0, a third in the plane z = x - y.
    for (int i = 0; i < 6; ++i) {
      const std::int64_t x = coordinate(rng), y = coordinate(rng), z = coordinate(rng);
      c.points.push_back({x, y, trial % 3 == 0 ? z : trial % 3 == 1 ? 0 : x - y});
    }
    c.t = {0, 1, 2};
    c.u = shape;
    for (const Triangle& f : {c.t, c.u}) {
      T x;
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) x[i][k] = static_cast<double>(c.points[f[i]][k]);
      ASSERT_EQ(is_degenerate(x), int_degenerate(c, f));
    }
    if (int_degenerate(c, c.t) || int_degenerate(c, c.u)) continue;
    ++tested;
    const IntVec nt = cross(c.points[1] - c.points[0], c.points[2] - c.points[0]);
    bool all_on_plane = true;
    for (Index k : c.u) all_on_plane &= dot(nt, c.points[k] - c.points[0]) == 0;
    coplanar += all_on_plane;
    const bool expected = oracle(c);
    intersecting += expected;
    std::array<int, 3> tperm = {0, 1, 2};
    do {
      std::array<int, 3> uperm = {0, 1, 2};
      do {
        for (bool swap : {false, true})
          ASSERT_EQ(evaluate(c, tperm, uperm, swap), expected)
              << "trial " << trial << " tperm " << tperm[0] << tperm[1] << tperm[2] << " uperm "
              << uperm[0] << uperm[1] << uperm[2] << " swap " << swap;
      } while (std::next_permutation(uperm.begin(), uperm.end()));
    } while (std::next_permutation(tperm.begin(), tperm.end()));
  }
  // The generator must produce both answers and plenty of coplanar configurations.
  EXPECT_GT(tested, trials / 4);
  EXPECT_GT(intersecting, tested / 20);
  EXPECT_LT(intersecting, tested - tested / 20);
  EXPECT_GT(coplanar, tested / 4);
}

TEST(RandomConfigurations, NoSharedVertexMatchesSeparatingAxisOracle) {
  check_random_cases(20000, 3, {3, 4, 5}, 1);
  check_random_cases(20000, 2, {3, 4, 5}, 2);
}

TEST(RandomConfigurations, SharedVertexMatchesTruncationOracle) {
  check_random_cases(20000, 3, {3, 0, 4}, 3);
  check_random_cases(20000, 2, {3, 0, 4}, 4);
}

TEST(RandomConfigurations, SharedEdgeMatchesFoldOracle) {
  check_random_cases(20000, 2, {3, 1, 0}, 5);
  check_random_cases(20000, 1, {3, 1, 0}, 6);
}

}  // namespace
}  // namespace vorocrust::geometry
