// Triangle-triangle intersection from orientation signs only.
//
// Non-coplanar triangles meet along the line where their planes cross, and there each triangle
// covers a segment whose ends lie on its boundary; the segments overlap iff an end of one lies
// in the other triangle, i.e. iff an edge of one triangle meets the other triangle. Coplanar
// triangles are handled in a 2D projection, where the same orientation signs answer exactly.
#include "geometry/triangle_intersection.hpp"

#include <Eigen/Geometry>
#include <optional>
#include <utility>

#include "geometry/predicates.hpp"

namespace vorocrust::geometry {
namespace {

int orient2d(const Point& a, const Point& b, const Point& c, Projection p) {
  return geometry::orient2d(a[p.x], a[p.y], b[p.x], b[p.y], c[p.x], c[p.y]);
}

bool mixed_signs(int a, int b, int c) {
  return (a > 0 || b > 0 || c > 0) && (a < 0 || b < 0 || c < 0);
}

bool strictly_one_side(int a, int b, int c) { return a == b && b == c && a != 0; }

// --- Coplanar tests, in a projection that is a bijection of the common plane. ---

// A point is in a closed non-degenerate triangle iff it is on no edge's outer side; with the
// triangle's orientation unknown, that means the three edge signs are not mixed.
bool point_in_triangle_2d(const Point& p, const TriangleCorners& t, Projection pr) {
  return !mixed_signs(orient2d(t[0], t[1], p, pr), orient2d(t[1], t[2], p, pr),
                      orient2d(t[2], t[0], p, pr));
}

bool lexicographically_less(const Point& a, const Point& b, Projection pr) {
  return a[pr.x] < b[pr.x] || (a[pr.x] == b[pr.x] && a[pr.y] < b[pr.y]);
}

bool segments_meet_2d(const Point& p, const Point& q, const Point& r, const Point& s,
                      Projection pr) {
  const int r_side = orient2d(p, q, r, pr), s_side = orient2d(p, q, s, pr);
  const int p_side = orient2d(r, s, p, pr), q_side = orient2d(r, s, q, pr);
  if (r_side * s_side > 0 || p_side * q_side > 0) return false;
  if (r_side != 0 || s_side != 0) return true;
  // All four collinear. Lexicographic order is monotone along any line, so the segments
  // overlap iff their lexicographic intervals do.
  const auto [p_lo, p_hi] = lexicographically_less(q, p, pr) ? std::pair(q, p) : std::pair(p, q);
  const auto [r_lo, r_hi] = lexicographically_less(s, r, pr) ? std::pair(s, r) : std::pair(r, s);
  return !lexicographically_less(p_hi, r_lo, pr) && !lexicographically_less(r_hi, p_lo, pr);
}

// A segment meets a triangle iff it starts inside it or crosses its boundary.
bool segment_meets_triangle_2d(const Point& p, const Point& q, const TriangleCorners& t,
                               Projection pr) {
  return point_in_triangle_2d(p, t, pr) || segments_meet_2d(p, q, t[0], t[1], pr) ||
         segments_meet_2d(p, q, t[1], t[2], pr) || segments_meet_2d(p, q, t[2], t[0], pr);
}

bool triangles_meet_2d(const TriangleCorners& t, const TriangleCorners& u, Projection pr) {
  for (int i = 0; i < 3; ++i)
    if (segment_meets_triangle_2d(t[i], t[(i + 1) % 3], u, pr)) return true;
  // No edge of t meets u: either u lies inside t or they are apart.
  return point_in_triangle_2d(u[0], t, pr);
}

// --- 3D tests. ---

// Closed segment pq against closed triangle t, given the sides of p and q w.r.t. t's plane.
bool segment_meets_triangle(const Point& p, const Point& q, int p_side, int q_side,
                            const TriangleCorners& t, Projection t_projection) {
  if (p_side == q_side) {
    if (p_side != 0) return false;
    return segment_meets_triangle_2d(p, q, t, t_projection);
  }
  // The segment reaches t's plane at exactly one point. The line pq passes through the closed
  // triangle iff it passes no edge on the outside, i.e. iff the orientations of pq against the
  // three edges, taken around the triangle, are not mixed.
  return !mixed_signs(orient3d(p, q, t[0], t[1]), orient3d(p, q, t[1], t[2]),
                      orient3d(p, q, t[2], t[0]));
}

bool closed_triangles_meet(const TriangleCorners& t, Projection tp, const TriangleCorners& u,
                           Projection up) {
  int u_side[3];
  for (int i = 0; i < 3; ++i) u_side[i] = orient3d(t[0], t[1], t[2], u[i]);
  if (strictly_one_side(u_side[0], u_side[1], u_side[2])) return false;
  if (u_side[0] == 0 && u_side[1] == 0 && u_side[2] == 0) return triangles_meet_2d(t, u, tp);
  int t_side[3];
  for (int i = 0; i < 3; ++i) t_side[i] = orient3d(u[0], u[1], u[2], t[i]);
  if (strictly_one_side(t_side[0], t_side[1], t_side[2])) return false;
  for (int i = 0, j = 1; i < 3; ++i, j = (j + 1) % 3) {
    if (segment_meets_triangle(u[i], u[j], u_side[i], u_side[j], t, tp)) return true;
    if (segment_meets_triangle(t[i], t[j], t_side[i], t_side[j], u, up)) return true;
  }
  return false;
}

// Corner 0 of t and u is the shared vertex v. Near v each triangle is a convex wedge of angle
// below pi; in a common plane two such wedges share more than v iff a bounding ray of one lies
// in the other (like two arcs shorter than a half circle).
bool wedges_overlap(const TriangleCorners& t, const TriangleCorners& u, Projection pr) {
  auto in_wedge = [pr](const TriangleCorners& w, const Point& p) {
    const int turn = orient2d(w[0], w[1], w[2], pr);
    return turn * orient2d(w[0], w[1], p, pr) >= 0 && turn * orient2d(w[0], p, w[2], pr) >= 0;
  };
  return in_wedge(t, u[1]) || in_wedge(t, u[2]) || in_wedge(u, t[1]) || in_wedge(u, t[2]);
}

// Corner 0 of t and u is the shared vertex v. Off a common plane the two triangles meet on the
// line through v where their planes cross, each covering a segment from v along it; the
// segments overlap beyond v iff the shorter one's far end, which lies on its triangle's edge
// opposite v, is in the other triangle.
bool shared_vertex_improper(const TriangleCorners& t, Projection tp, const TriangleCorners& u,
                            Projection up) {
  const int u1_side = orient3d(t[0], t[1], t[2], u[1]);
  const int u2_side = orient3d(t[0], t[1], t[2], u[2]);
  if (u1_side == 0 && u2_side == 0) return wedges_overlap(t, u, tp);
  if (u1_side == u2_side) return false;  // u touches t's plane at v only
  const int t1_side = orient3d(u[0], u[1], u[2], t[1]);
  const int t2_side = orient3d(u[0], u[1], u[2], t[2]);
  if (t1_side == t2_side && t1_side != 0) return false;
  return segment_meets_triangle(u[1], u[2], u1_side, u2_side, t, tp) ||
         segment_meets_triangle(t[1], t[2], t1_side, t2_side, u, up);
}

// Triangles abp and abq on a shared edge ab. Off a common plane they meet only on line ab, which
// each meets only in ab itself; in a common plane they overlap iff p and q are on the same side
// of ab (the faces fold onto each other).
bool shared_edge_improper(const Point& a, const Point& b, const Point& p, const Point& q,
                          Projection tp) {
  if (orient3d(a, b, p, q) != 0) return false;
  return orient2d(a, b, p, tp) == orient2d(a, b, q, tp);
}

TriangleCorners rotated(const TriangleCorners& t, int first) {
  return {t[first], t[(first + 1) % 3], t[(first + 2) % 3]};
}

}  // namespace

// A projection that keeps t non-degenerate, or none when t has zero area. The projected area
// along axis k is exactly the k-th component of t's normal, so orient2d certifies the choice;
// the largest floating normal component merely suggests which axis to try first.
std::optional<Projection> projection_of(const TriangleCorners& t) {
  const Point n = (t[1] - t[0]).cross(t[2] - t[0]).cwiseAbs();
  int order[3] = {0, 1, 2};
  if (n[order[1]] > n[order[0]]) std::swap(order[0], order[1]);
  if (n[order[2]] > n[order[0]]) std::swap(order[0], order[2]);
  for (int dropped : order) {
    const Projection p{(dropped + 1) % 3, (dropped + 2) % 3};
    if (orient2d(t[0], t[1], t[2], p) != 0) return p;
  }
  return std::nullopt;
}

SharedCorners shared_corners(const Triangle& first, const Triangle& second) {
  SharedCorners shared = kNoSharedCorners;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (first[i] == second[j]) {
        shared[i] = j;
        break;
      }
  return shared;
}

bool is_degenerate(const TriangleCorners& t) { return !projection_of(t).has_value(); }

bool improperly_intersect(const TriangleCorners& t, const TriangleCorners& u,
                          const SharedCorners& shared) {
  const std::optional<Projection> tp = projection_of(t);
  const std::optional<Projection> up = projection_of(u);
  if (!tp || !up) return false;
  int count = 0, t_shared = -1, t_unshared = -1;
  for (int i = 0; i < 3; ++i) {
    if (shared[i] >= 0) {
      ++count;
      t_shared = i;
    } else {
      t_unshared = i;
    }
  }
  switch (count) {
    case 0:
      return closed_triangles_meet(t, *tp, u, *up);
    case 1:
      // Rotating corners leaves each plane, hence each projection, unchanged.
      return shared_vertex_improper(rotated(t, t_shared), *tp, rotated(u, shared[t_shared]), *up);
    case 2: {
      const int a = (t_unshared + 1) % 3, b = (t_unshared + 2) % 3;
      // Corners of a non-degenerate triangle are distinct, so the unshared one of u is the
      // corner index left over.
      const int u_unshared = 3 - shared[a] - shared[b];
      return shared_edge_improper(t[a], t[b], t[t_unshared], u[u_unshared], *tp);
    }
    default:
      return false;  // the same three vertices: a duplicate face
  }
}

}  // namespace vorocrust::geometry
