// Where faces cut each other: arrangement, before the features (2.2).
#include "arrangement/face_cuts.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <compare>
#include <cstdint>
#include <map>
#include <set>

#include "core/edge_topology.hpp"
#include "geometry/predicates.hpp"
#include "geometry/triangle_intersection.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust::arrangement {
namespace {

using geometry::orient3d;
using Edge = std::array<Index, 2>;  // (smaller, larger) vertex

Edge edge_of(Index a, Index b) { return a < b ? Edge{a, b} : Edge{b, a}; }

// What a point of the arrangement lies on; the name every face holding the point shares.
struct PointName {
  enum Kind : std::uint8_t { Vertex, EdgeFace, EdgeEdge, ThreeFaces } kind;
  std::array<Index, 4> ids;
  auto operator<=>(const PointName&) const = default;
};

PointName vertex_point(Index v) { return {PointName::Vertex, {v, 0, 0, 0}}; }
PointName edge_face_point(Edge e, Index f) { return {PointName::EdgeFace, {e[0], e[1], f, 0}}; }
PointName edge_edge_point(Edge e, Edge g) {
  if (g < e) std::swap(e, g);
  return {PointName::EdgeEdge, {e[0], e[1], g[0], g[1]}};
}

int sign_count(const int (&s)[3], int sign) { return (s[0] == sign) + (s[1] == sign) + (s[2] == sign); }

class CutFinder {
 public:
  explicit CutFinder(const SurfaceMesh& mesh) : mesh_(mesh), points_(mesh.vertices) {}

  void cut(Index a, Index b) {
    const auto ta = corners(a), tb = corners(b);
    int a_side[3], b_side[3];
    for (int i = 0; i < 3; ++i) {
      a_side[i] = orient3d(tb[0], tb[1], tb[2], ta[i]);
      b_side[i] = orient3d(ta[0], ta[1], ta[2], tb[i]);
    }
    if (sign_count(a_side, 0) == 3) {
      throw Error(Error::Kind::InvalidGeometry,
                  describe_face(mesh_, a) + " and " + describe_face(mesh_, b) +
                      " overlap in a common plane; self-intersections are resolved only where faces cross",
                  {.face = a});
    }
    std::vector<Index> chain;
    boundary_meets(a, b, a_side, chain);
    boundary_meets(b, a, b_side, chain);
    std::sort(chain.begin(), chain.end());
    chain.erase(std::unique(chain.begin(), chain.end()), chain.end());
    if (chain.size() >= 2) chains_[{a, b}] = std::move(chain);
  }

  // Where the curves of faces a and b and of a and c cross inside a, b and c (all three pairs
  // cross): the one point of the three planes, named by the three faces.
  void add_crossings_of_curves() {
    std::map<Index, std::vector<Index>> partners;
    for (const auto& [pair, chain] : chains_) {
      partners[pair.first].push_back(pair.second);
      partners[pair.second].push_back(pair.first);
    }
    for (auto& [f, list] : partners) std::sort(list.begin(), list.end());
    for (const auto& [a, list] : partners) {
      for (std::size_t i = 0; i < list.size(); ++i) {
        const Index b = list[i];
        if (b < a) continue;
        for (std::size_t j = i + 1; j < list.size(); ++j) {
          const Index c = list[j];
          if (!chains_.contains({b, c})) continue;
          const std::optional<Point> x = common_point(a, b, c);
          if (!x) continue;
          const Index p = point({PointName::ThreeFaces, {a, b, c, 0}}, *x);
          for (const auto& pair : {std::pair{a, b}, std::pair{a, c}, std::pair{b, c}}) chains_[pair].push_back(p);
        }
      }
    }
  }

  FaceCuts result() {
    FaceCuts cuts;
    std::set<Index> faces;
    const EdgeTopology topology = build_edge_topology(mesh_);
    for (const auto& [edge, list] : edge_points_) {
      const auto it = std::lower_bound(topology.edges.begin(), topology.edges.end(), edge);
      for (Index f : topology.faces_of(static_cast<std::size_t>(it - topology.edges.begin()))) faces.insert(f);
    }
    for (const auto& [f, list] : inner_points_) faces.insert(f);
    std::map<Index, std::vector<const std::vector<Index>*>> chains_of;
    for (auto& [pair, chain] : chains_) {
      sort_along_curve(pair.first, pair.second, chain);
      faces.insert(pair.first);
      faces.insert(pair.second);
      chains_of[pair.first].push_back(&chain);
      chains_of[pair.second].push_back(&chain);
    }
    for (Index f : faces) {
      FaceCut cut;
      const Triangle& t = mesh_.triangles[f];
      for (int i = 0; i < 3; ++i) {
        const auto it = edge_points_.find(edge_of(t[i], t[(i + 1) % 3]));
        if (it == edge_points_.end()) continue;
        cut.edge_points[i] = it->second;
        sort_along(mesh_.vertices[t[i]], mesh_.vertices[t[(i + 1) % 3]], cut.edge_points[i]);
      }
      if (const auto it = inner_points_.find(f); it != inner_points_.end()) cut.inner_points = it->second;
      for (const std::vector<Index>* chain : chains_of[f]) {
        for (std::size_t k = 0; k + 1 < chain->size(); ++k) cut.segments.push_back({(*chain)[k], (*chain)[k + 1]});
      }
      // Chain points inside the face that no edge or vertex brought (curve crossings).
      for (const std::vector<Index>* chain : chains_of[f]) {
        for (Index p : *chain) {
          if (named_kind(p) == PointName::ThreeFaces) cut.inner_points.push_back(p);
        }
      }
      std::sort(cut.inner_points.begin(), cut.inner_points.end());
      cut.inner_points.erase(std::unique(cut.inner_points.begin(), cut.inner_points.end()), cut.inner_points.end());
      cuts.cut_faces.push_back(f);
      cuts.of_cut_face.push_back(std::move(cut));
    }
    cuts.points = std::move(points_);
    return cuts;
  }

 private:
  std::array<Point, 3> corners(Index f) const {
    const Triangle& t = mesh_.triangles[f];
    return {mesh_.vertices[t[0]], mesh_.vertices[t[1]], mesh_.vertices[t[2]]};
  }

  Index point(const PointName& name, const Point& position) {
    if (name.kind == PointName::Vertex) return name.ids[0];
    const auto [it, fresh] = named_.try_emplace(name, static_cast<Index>(points_.size()));
    if (fresh) {
      points_.push_back(position);
      kinds_.push_back(name.kind);
    }
    return it->second;
  }

  PointName::Kind named_kind(Index p) const {
    return p < mesh_.num_vertices() ? PointName::Vertex : kinds_[p - mesh_.num_vertices()];
  }

  void on_edge(Edge e, Index p) {
    std::vector<Index>& list = edge_points_[e];
    if (p != e[0] && p != e[1] && std::find(list.begin(), list.end(), p) == list.end()) list.push_back(p);
  }

  void in_face(Index f, Index p) {
    std::vector<Index>& list = inner_points_[f];
    if (std::find(list.begin(), list.end(), p) == list.end()) list.push_back(p);
  }

  // The points where face a's boundary meets the closed face b, given the side of b's plane
  // each corner of a lies on; each is registered with the faces holding it and added to chain.
  void boundary_meets(Index a, Index b, const int (&side)[3], std::vector<Index>& chain) {
    const Triangle& ta = mesh_.triangles[a];
    const Triangle& tb = mesh_.triangles[b];
    const auto cb = corners(b);
    // Corners of a in b's plane: inside b, on one of its edges, or on one of its vertices.
    const std::optional<geometry::Projection> pb = geometry::projection_of(cb);
    for (int i = 0; i < 3; ++i) {
      if (side[i] != 0) continue;
      const Point& p = mesh_.vertices[ta[i]];
      const auto o2 = [&](const Point& u, const Point& v, const Point& w) {
        return geometry::orient2d(u[pb->x], u[pb->y], v[pb->x], v[pb->y], w[pb->x], w[pb->y]);
      };
      const int turn = o2(cb[0], cb[1], cb[2]);
      int s[3];
      for (int k = 0; k < 3; ++k) s[k] = turn * o2(cb[k], cb[(k + 1) % 3], p);
      if (sign_count(s, -1) > 0) continue;
      const Index v = point(vertex_point(ta[i]), p);
      if (sign_count(s, 0) == 0) {
        in_face(b, v);
      } else if (sign_count(s, 0) == 1) {
        const int k = s[0] == 0 ? 0 : s[1] == 0 ? 1 : 2;
        on_edge(edge_of(tb[k], tb[(k + 1) % 3]), v);
      } else {
        const int k = s[0] != 0 ? 2 : s[1] != 0 ? 0 : 1;  // the corner between the two zero edges
        if (tb[k] != ta[i]) coincident(ta[i], tb[k], a, b);
      }
      chain.push_back(v);
    }
    // Edges of a crossing b's plane: through b's inside, across one of its edges, or through
    // one of its vertices (which lies on the edge).
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      if (side[i] * side[j] >= 0) continue;
      const Point& p = mesh_.vertices[ta[i]];
      const Point& q = mesh_.vertices[ta[j]];
      int s[3];
      for (int k = 0; k < 3; ++k) s[k] = orient3d(p, q, cb[k], cb[(k + 1) % 3]);
      if (sign_count(s, 1) > 0 && sign_count(s, -1) > 0) continue;
      const Edge e = edge_of(ta[i], ta[j]);
      Index x;
      if (sign_count(s, 0) == 0) {
        x = point(edge_face_point(e, b), plane_crossing(p, q, cb));
        in_face(b, x);
      } else if (sign_count(s, 0) == 1) {
        const int k = s[0] == 0 ? 0 : s[1] == 0 ? 1 : 2;
        const Edge g = edge_of(tb[k], tb[(k + 1) % 3]);
        x = point(edge_edge_point(e, g), plane_crossing(p, q, cb));
        on_edge(g, x);
      } else {
        const int k = s[0] != 0 ? 2 : s[1] != 0 ? 0 : 1;
        x = point(vertex_point(tb[k]), mesh_.vertices[tb[k]]);
      }
      on_edge(e, x);
      chain.push_back(x);
    }
  }

  // Where segment pq, whose ends lie strictly on either side, crosses the plane of t.
  static Point plane_crossing(const Point& p, const Point& q, const std::array<Point, 3>& t) {
    const Point n = (t[1] - t[0]).cross(t[2] - t[0]);
    const double dp = n.dot(p - t[0]), dq = n.dot(q - t[0]);
    const double s = std::clamp(dp / (dp - dq), 0.0, 1.0);
    return p + s * (q - p);
  }

  std::optional<Point> common_point(Index a, Index b, Index c) const {
    Eigen::Matrix3d normals;
    Eigen::Vector3d offsets;
    const Index faces[3] = {a, b, c};
    for (int r = 0; r < 3; ++r) {
      const auto t = corners(faces[r]);
      const Point n = (t[1] - t[0]).cross(t[2] - t[0]).normalized();
      normals.row(r) = n.transpose();
      offsets[r] = n.dot(t[0]);
    }
    const Eigen::FullPivLU<Eigen::Matrix3d> lu(normals);
    if (!lu.isInvertible()) return std::nullopt;
    const Point x = lu.solve(offsets);
    for (Index f : faces) {
      if (!strictly_inside(f, x)) return std::nullopt;
    }
    return x;
  }

  // Whether x, a point of f's plane up to rounding, lies inside f away from its edges.
  bool strictly_inside(Index f, const Point& x) const {
    const auto t = corners(f);
    const Point n = (t[1] - t[0]).cross(t[2] - t[0]);
    for (int k = 0; k < 3; ++k) {
      if (n.dot((t[(k + 1) % 3] - t[k]).cross(x - t[k])) <= 0) return false;
    }
    return true;
  }

  [[noreturn]] void coincident(Index u, Index v, Index a, Index b) const {
    throw Error(Error::Kind::InvalidGeometry,
                "vertices " + std::to_string(u) + " and " + std::to_string(v) + " of " + describe_face(mesh_, a) +
                    " and " + describe_face(mesh_, b) + " lie at one position; weld them before meshing",
                {.face = a});
  }

  // Ascending along the line the two faces' planes share.
  void sort_along_curve(Index a, Index b, std::vector<Index>& chain) const {
    const auto ta = corners(a), tb = corners(b);
    const Point d = (ta[1] - ta[0]).cross(ta[2] - ta[0]).cross((tb[1] - tb[0]).cross(tb[2] - tb[0]));
    std::sort(chain.begin(), chain.end());
    chain.erase(std::unique(chain.begin(), chain.end()), chain.end());
    std::stable_sort(chain.begin(), chain.end(),
                     [&](Index p, Index q) { return d.dot(points_[p]) < d.dot(points_[q]); });
  }

  void sort_along(const Point& from, const Point& to, std::vector<Index>& list) const {
    const Point d = to - from;
    std::stable_sort(list.begin(), list.end(),
                     [&](Index p, Index q) { return d.dot(points_[p] - from) < d.dot(points_[q] - from); });
  }

  const SurfaceMesh& mesh_;
  std::vector<Point> points_;
  std::vector<PointName::Kind> kinds_;  // of the new points
  std::map<PointName, Index> named_;
  std::map<Edge, std::vector<Index>> edge_points_;
  std::map<Index, std::vector<Index>> inner_points_;
  std::map<std::pair<Index, Index>, std::vector<Index>> chains_;  // by face pair, smaller first
};

}  // namespace

FaceCuts find_face_cuts(const SurfaceMesh& mesh, std::span<const geometry::FacePair> pairs) {
  CutFinder finder(mesh);
  for (const auto& [a, b] : pairs) finder.cut(static_cast<Index>(a), static_cast<Index>(b));
  finder.add_crossings_of_curves();
  return finder.result();
}

}  // namespace vorocrust::arrangement
