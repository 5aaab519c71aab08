// One face split along its cuts: arrangement, before the features (2.2).
#include "arrangement/triangulate_cut_face.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <deque>
#include <optional>
#include <set>
#include <string>

#include "geometry/predicates.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust::arrangement {
namespace {

using Corners = std::array<int, 3>;  // counter-clockwise

// A constrained triangulation of a handful of points in the plane, built by splitting the face
// triangle: small enough that finding a triangle by scanning them all costs less than keeping
// adjacency up to date.
class PlaneTriangulation {
 public:
  explicit PlaneTriangulation(std::vector<Eigen::Vector2d> xy) : xy_(std::move(xy)) { triangles_.push_back({0, 1, 2}); }

  int orient(int a, int b, int c) const {
    return geometry::orient2d(xy_[a].x(), xy_[a].y(), xy_[b].x(), xy_[b].y(), xy_[c].x(), xy_[c].y());
  }

  // Point p on the boundary edge from a to b (the face's corners run counter-clockwise).
  bool split_boundary_edge(int a, int b, int p) {
    const auto found = with_edge(a, b);
    if (!found) return false;
    const auto [t, k] = *found;
    const int w = triangles_[t][(k + 2) % 3];
    triangles_[t] = {a, p, w};
    triangles_.push_back({p, b, w});
    return true;
  }

  bool insert_inner(int p) {
    for (std::size_t t = 0; t < triangles_.size(); ++t) {
      const Corners c = triangles_[t];
      int s[3];
      for (int k = 0; k < 3; ++k) s[k] = orient(c[k], c[(k + 1) % 3], p);
      if (s[0] < 0 || s[1] < 0 || s[2] < 0) continue;
      const int zeros = (s[0] == 0) + (s[1] == 0) + (s[2] == 0);
      if (zeros == 0) {
        triangles_[t] = {c[0], c[1], p};
        triangles_.push_back({c[1], c[2], p});
        triangles_.push_back({c[2], c[0], p});
        return true;
      }
      if (zeros > 1) return false;  // on a vertex
      const int k = s[0] == 0 ? 0 : s[1] == 0 ? 1 : 2;
      const int a = c[k], b = c[(k + 1) % 3], w = c[(k + 2) % 3];
      const auto across = with_edge(b, a);
      if (!across) return false;  // on the face's boundary
      const int x = triangles_[across->first][(across->second + 2) % 3];
      triangles_[t] = {a, p, w};
      triangles_.push_back({p, b, w});
      triangles_[across->first] = {b, p, x};
      triangles_.push_back({p, a, x});
      return true;
    }
    return false;
  }

  // Makes pq an edge by flipping the edges that cross it (Sloan's method); a vertex on pq
  // splits it in two.
  bool insert_segment(int p, int q) {
    if (p == q) return true;
    if (with_edge(p, q) || with_edge(q, p)) {
      constrained_.insert(undirected(p, q));
      return true;
    }
    std::optional<int> on_segment;
    for (int r = 0; r < static_cast<int>(xy_.size()); ++r) {
      if (r == p || r == q || orient(p, q, r) != 0) continue;
      const Eigen::Vector2d d = xy_[q] - xy_[p];
      if (d.dot(xy_[r] - xy_[p]) <= 0 || d.dot(xy_[r] - xy_[q]) >= 0) continue;
      if (!on_segment || d.dot(xy_[r] - xy_[p]) < d.dot(xy_[*on_segment] - xy_[p])) on_segment = r;
    }
    if (on_segment) return insert_segment(p, *on_segment) && insert_segment(*on_segment, q);

    std::deque<std::pair<int, int>> crossing;
    for (const Corners& c : triangles_) {
      for (int k = 0; k < 3; ++k) {
        const int u = c[k], v = c[(k + 1) % 3];
        if (u < v && crosses(p, q, u, v)) {
          if (constrained_.contains(undirected(u, v))) return false;  // two cuts cross at no shared point
          crossing.emplace_back(u, v);
        }
      }
    }
    // Each flip either removes a crossing or makes progress around a non-convex quadrilateral;
    // the bound only guards against rounding having made the configuration inconsistent.
    for (std::size_t guard = 0; !crossing.empty(); ++guard) {
      if (guard > 64 * (crossing.size() + xy_.size()) + 1024) return false;
      const auto [u, v] = crossing.front();
      crossing.pop_front();
      const std::optional<std::pair<int, int>> flipped = flip(u, v);
      if (!flipped) {
        crossing.emplace_back(u, v);
        continue;
      }
      const auto [w, x] = *flipped;
      if (crosses(p, q, w, x)) crossing.emplace_back(w, x);
    }
    if (!with_edge(p, q) && !with_edge(q, p)) return false;
    constrained_.insert(undirected(p, q));
    return true;
  }

  // Lawson flips of unconstrained edges towards Delaunay; a tolerance keeps cocircular points
  // from flipping back and forth.
  void improve() {
    for (int pass = 0; pass < 32; ++pass) {
      bool changed = false;
      for (std::size_t t = 0; t < triangles_.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
          const int u = triangles_[t][k], v = triangles_[t][(k + 1) % 3], w = triangles_[t][(k + 2) % 3];
          if (constrained_.contains(undirected(u, v))) continue;
          const auto across = with_edge(v, u);
          if (!across) continue;
          const int x = triangles_[across->first][(across->second + 2) % 3];
          if (in_circle(u, v, w, x) && flip(u, v)) {
            changed = true;
            break;
          }
        }
      }
      if (!changed) return;
    }
  }

  bool all_positive() const {
    return std::all_of(triangles_.begin(), triangles_.end(),
                       [&](const Corners& c) { return orient(c[0], c[1], c[2]) > 0; });
  }

  const std::vector<Corners>& triangles() const { return triangles_; }

 private:
  static std::pair<int, int> undirected(int a, int b) { return a < b ? std::pair{a, b} : std::pair{b, a}; }

  // The triangle running from a to b, and the position of a in it.
  std::optional<std::pair<std::size_t, int>> with_edge(int a, int b) const {
    for (std::size_t t = 0; t < triangles_.size(); ++t) {
      for (int k = 0; k < 3; ++k) {
        if (triangles_[t][k] == a && triangles_[t][(k + 1) % 3] == b) return std::pair{t, k};
      }
    }
    return std::nullopt;
  }

  // Whether segments pq and uv cross at a point inside both.
  bool crosses(int p, int q, int u, int v) const {
    if (u == p || u == q || v == p || v == q) return false;
    return orient(p, q, u) * orient(p, q, v) < 0 && orient(u, v, p) * orient(u, v, q) < 0;
  }

  // Replaces edge uv by the other diagonal of its two triangles when they form a strictly
  // convex quadrilateral; returns that diagonal.
  std::optional<std::pair<int, int>> flip(int u, int v) {
    auto first = with_edge(u, v), second = with_edge(v, u);
    if (!first || !second) {
      first = with_edge(v, u);
      second = with_edge(u, v);
      std::swap(u, v);
      if (!first || !second) return std::nullopt;
    }
    const int w = triangles_[first->first][(first->second + 2) % 3];
    const int x = triangles_[second->first][(second->second + 2) % 3];
    if (orient(u, x, w) <= 0 || orient(x, v, w) <= 0) return std::nullopt;
    triangles_[first->first] = {u, x, w};
    triangles_[second->first] = {x, v, w};
    return std::pair{w, x};
  }

  // Whether x lies clearly inside the circle through u, v, w (counter-clockwise).
  bool in_circle(int u, int v, int w, int x) const {
    const Eigen::Vector2d a = xy_[u] - xy_[x], b = xy_[v] - xy_[x], c = xy_[w] - xy_[x];
    const double det = (a.squaredNorm()) * (b.x() * c.y() - b.y() * c.x()) -
                       (b.squaredNorm()) * (a.x() * c.y() - a.y() * c.x()) +
                       (c.squaredNorm()) * (a.x() * b.y() - a.y() * b.x());
    const double scale = a.squaredNorm() + b.squaredNorm() + c.squaredNorm();
    return det > 1e-10 * scale * scale;
  }

  std::vector<Eigen::Vector2d> xy_;
  std::vector<Corners> triangles_;
  std::set<std::pair<int, int>> constrained_;
};

}  // namespace

std::vector<Triangle> triangulate_cut_face(const SurfaceMesh& mesh, Index face, const FaceCut& cut,
                                           const std::vector<Point>& points) {
  const Triangle& corners = mesh.triangles[face];
  // Local numbering: the corners, the edge points edge by edge, then the inner points.
  std::vector<Index> global(corners.begin(), corners.end());
  for (const auto& list : cut.edge_points) global.insert(global.end(), list.begin(), list.end());
  global.insert(global.end(), cut.inner_points.begin(), cut.inner_points.end());
  const auto fail = [&](const std::string& what) -> std::vector<Triangle> {
    throw Error(Error::Kind::InvalidGeometry,
                "cannot resolve the self-intersections of " + describe_face(mesh, face) + ": " + what,
                {.face = face});
  };
  const auto local = [&](Index g) {
    return static_cast<int>(std::find(global.begin(), global.end(), g) - global.begin());
  };

  const Point a = points[corners[0]], b = points[corners[1]], c = points[corners[2]];
  const Point n = (b - a).cross(c - a);
  int drop = 0;
  n.cwiseAbs().maxCoeff(&drop);
  // Keep the face counter-clockwise in the plane: mirror when the dropped axis looks down.
  int x = (drop + 1) % 3, y = (drop + 2) % 3;
  if (n[drop] < 0) std::swap(x, y);
  std::vector<Eigen::Vector2d> xy;
  xy.reserve(global.size());
  for (Index g : global) xy.emplace_back(points[g][x], points[g][y]);

  PlaneTriangulation triangulation(std::move(xy));
  if (triangulation.orient(0, 1, 2) <= 0) return fail("the face has no area in its plane");
  int next = 3;
  for (int i = 0; i < 3; ++i) {
    int previous = i;
    for (std::size_t k = 0; k < cut.edge_points[i].size(); ++k, ++next) {
      if (!triangulation.split_boundary_edge(previous, (i + 1) % 3, next)) return fail("an edge point was lost");
      previous = next;
    }
  }
  for (; next < static_cast<int>(global.size()); ++next) {
    if (!triangulation.insert_inner(next)) return fail("a crossing point falls on its boundary or outside it");
  }
  for (const auto& [p, q] : cut.segments) {
    if (!triangulation.insert_segment(local(p), local(q))) {
      return fail("two intersection curves cross where no common point was found");
    }
  }
  triangulation.improve();
  if (!triangulation.all_positive()) return fail("a piece is turned over");

  std::vector<Triangle> pieces;
  pieces.reserve(triangulation.triangles().size());
  for (const Corners& t : triangulation.triangles()) pieces.push_back({global[t[0]], global[t[1]], global[t[2]]});
  return pieces;
}

}  // namespace vorocrust::arrangement
