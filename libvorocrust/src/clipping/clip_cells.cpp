#include "clipping/clip_cells.hpp"

#include <tbb/parallel_for.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <compare>
#include <iterator>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "cells/renumber_points.hpp"
#include "clipping/polygon_holes.hpp"
#include "core/c_format.hpp"
#include "core/union_find.hpp"
#include "geometry/measure_cells.hpp"
#include "geometry/point_cloud.hpp"
#include "seeds/locate_regions.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust::clipping {
namespace {

using CellId = std::uint32_t;

// What defines a point of the clipped mesh: equal keys are one point, computed one way.
enum class KeyKind : std::uint8_t { InputVertex, EdgeCut, TriangleCut, InterfaceCut };
struct Key {
  KeyKind kind = KeyKind::InputVertex;
  // InputVertex: v. EdgeCut: the edge's vertices u < w, the bisector's cells c < d.
  // TriangleCut: the triangle, the three cells c < d < e whose Voronoi edge meets it.
  // InterfaceCut: a triangle between two materials, a bisector of each material's cells (c < d,
  // e < f, (c, d) < (e, f)) that cross in it.
  std::array<std::uint32_t, 5> ids{};
  auto operator<=>(const Key&) const = default;
};

// The line a polygon edge lies on in its triangle: an input edge (u < w), or the bisector between
// the clipped cell and another.
struct Support {
  bool bisector = false;
  std::uint32_t a = 0, b = 0;  // edge: u, w; bisector: the clipped cell, the other
};

struct Corner {
  Key key;
  Point p;
  Support out;  // of the edge from this corner to the next
};
using Polygon = std::vector<Corner>;

constexpr CellId kNoneAcross = ~CellId{0};

// A part of an input triangle in one cell, in the triangle's vertex order. On a triangle between
// two materials, the part is in one cell of each (`across`, the other material's) and comes
// twice, once for each cell; the second copy is the `mirror`.
struct Piece {
  std::uint32_t triangle = 0;
  CellId cell = 0;
  Polygon corners;
  CellId across = kNoneAcross;
  bool mirror = false;
};

// A point of the surface on a Voronoi edge: where the edge of three cells crosses a triangle.
struct Crossing {
  std::array<CellId, 3> cells;
  Index point;
  std::uint32_t triangle;
  auto operator<=>(const Crossing&) const = default;
};

std::uint64_t pair_key(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

// The surface's restricted Voronoi diagram: each boundary triangle cut by the cells it meets,
// found by walking from the cell of its centroid across the bisectors that cut it (Yan et al.
// 4.1). A point's side of a bisector is computed from the point's key alone, so a part of an
// input edge is cut the same way in both its triangles. Each material has its own diagram; a
// triangle between two materials is cut by the first material's cells, then each part by the
// second's: the interface's faces are the overlay of both diagrams, one face per pair of cells.
class RestrictedCells {
 public:
  RestrictedCells(const VoronoiMesh& voronoi, const SurfaceMesh& domain) : domain_(domain) {
    sites_.reserve(voronoi.cells.size());
    for (const VoronoiCell& c : voronoi.cells) sites_.push_back(c.site);
    neighbours_.resize(voronoi.cells.size());
    beyond_.resize(voronoi.cells.size());
    for (std::size_t face = 0; face < voronoi.faces.size(); ++face) {
      const VoronoiFace& f = voronoi.faces[face];
      if (f.neighbour == kNoCell) {
        const FaceGeometry g = face_geometry(voronoi, face);
        beyond_[static_cast<std::size_t>(f.owner)].push_back({g.normal, g.normal.dot(g.centroid)});
        continue;
      }
      neighbours_[static_cast<std::size_t>(f.owner)].push_back(static_cast<CellId>(f.neighbour));
      neighbours_[static_cast<std::size_t>(f.neighbour)].push_back(static_cast<CellId>(f.owner));
    }
    // One order of the bisectors for every triangle: a part of an input edge is then cut by
    // the same planes in the same order in both triangles that share it.
    for (std::vector<CellId>& n : neighbours_) std::sort(n.begin(), n.end());
    for (CellId c = 0; c < voronoi.cells.size(); ++c) {
      std::unique_ptr<Diagram>& d = diagrams_[voronoi.cells[c].region];
      if (!d) d = std::make_unique<Diagram>();
      d->cells.push_back(c);
      d->sites.push_back(sites_[c]);
    }
    for (auto& [material, d] : diagrams_) {
      d->cloud.items = &d->sites;
      d->tree = std::make_unique<Tree>(3, d->cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
    }
  }

  bool meshes(std::int32_t region) const { return diagrams_.count(region) > 0; }

  // A triangle's parts in the cells, or none where part of it lies in an outside seed's cell.
  std::optional<std::vector<Piece>> pieces(std::uint32_t t) const {
    const Triangle& tri = domain_.triangles[t];
    Polygon triangle(3);
    for (int k = 0; k < 3; ++k) {
      const Index u = tri[k], w = tri[(k + 1) % 3];
      triangle[k] = {Key{KeyKind::InputVertex, {u, 0, 0, 0, 0}}, domain_.vertices[u],
                     Support{false, std::min(u, w), std::max(u, w)}};
    }
    const RegionPair& sides = domain_.face_regions[t];
    std::int32_t first = std::min(sides.back, sides.front), second = std::max(sides.back, sides.front);
    if (!meshes(first)) std::swap(first, second);
    std::vector<Piece> result;
    for (auto& [cell, polygon] : walk(t, triangle, first)) {
      if (reaches_outside(cell, polygon)) return std::nullopt;
      if (!meshes(second)) {
        result.push_back({t, cell, std::move(polygon)});
        continue;
      }
      for (auto& [other, part] : walk(t, polygon, second)) {
        if (reaches_outside(other, part)) return std::nullopt;
        result.push_back({t, cell, part, other, false});
        result.push_back({t, other, std::move(part), cell, true});
      }
    }
    return result;
  }

 private:
  using Cloud = PointCloudAdaptor<Point, IdentityPosition>;
  using Tree = StaticKdTree<Cloud>;
  struct Diagram {
    std::vector<CellId> cells;
    std::vector<Point> sites;
    Cloud cloud;
    std::unique_ptr<Tree> tree;
  };

  // The parts of the convex polygon `start`, in triangle t, in each cell of `material` it meets.
  std::vector<std::pair<CellId, Polygon>> walk(std::uint32_t t, const Polygon& start, std::int32_t material) const {
    Point centre = Point::Zero();
    for (const Corner& k : start) centre += k.p;
    const Diagram& d = *diagrams_.at(material);
    std::uint32_t index = 0;
    double squared = 0;
    d.tree->knnSearch(Point(centre / static_cast<double>(start.size())).data(), 1, &index, &squared);
    std::vector<CellId> visited{d.cells[index]};
    std::vector<std::pair<CellId, Polygon>> result;
    for (std::size_t q = 0; q < visited.size(); ++q) {
      const CellId c = visited[q];
      Polygon polygon = start;
      for (CellId x : neighbours_[c]) {
        polygon = clip(polygon, c, x, t);
        if (polygon.empty()) break;
      }
      if (polygon.empty()) continue;
      for (const Corner& k : polygon) {
        if (k.out.bisector && k.out.a == c && std::find(visited.begin(), visited.end(), k.out.b) == visited.end()) {
          visited.push_back(k.out.b);
        }
      }
      result.emplace_back(c, std::move(polygon));
    }
    return result;
  }

  // Whether a part of cell c's polygon lies beyond one of c's faces toward an outside seed:
  // nearer that seed than c's, where only a larger margin of outside seeds gives the surface its
  // cells. Cells only meet their material neighbours in the walk, so this is the test that sees it.
  bool reaches_outside(CellId c, const Polygon& polygon) const {
    for (const Plane& plane : beyond_[c]) {
      const double reach = std::abs(plane.offset - plane.normal.dot(sites_[c]));
      for (const Corner& k : polygon) {
        if (plane.normal.dot(k.p) - plane.offset > 1e-9 * reach) return true;
      }
    }
    return false;
  }

  // Positive where p is nearer cell hi's seed than cell lo's (lo < hi).
  double bisector_value(CellId lo, CellId hi, const Point& p) const {
    const Point& a = sites_[lo];
    const Point& b = sites_[hi];
    return (b - a).dot(2 * p - a - b);
  }

  static bool on_bisector(const Key& key, CellId c, CellId x) {
    const CellId lo = std::min(c, x), hi = std::max(c, x);
    switch (key.kind) {
      case KeyKind::EdgeCut: return key.ids[2] == lo && key.ids[3] == hi;
      case KeyKind::TriangleCut: {
        const auto has = [&](CellId k) { return key.ids[1] == k || key.ids[2] == k || key.ids[3] == k; };
        return has(lo) && has(hi);
      }
      case KeyKind::InterfaceCut:
        return (key.ids[1] == lo && key.ids[2] == hi) || (key.ids[3] == lo && key.ids[4] == hi);
      default: return false;
    }
  }

  // -1: nearer c's seed; 1: nearer x's; 0: on their bisector, by definition or exactly.
  int side(const Corner& k, CellId c, CellId x) const {
    if (on_bisector(k.key, c, x)) return 0;
    const double v = c < x ? bisector_value(c, x, k.p) : -bisector_value(x, c, k.p);
    return (v > 0) - (v < 0);
  }

  Point edge_cut(std::uint32_t u, std::uint32_t w, CellId lo, CellId hi) const {
    const Point& pu = domain_.vertices[u];
    const Point& pw = domain_.vertices[w];
    const double gu = bisector_value(lo, hi, pu), gw = bisector_value(lo, hi, pw);
    const double lambda = gu == gw ? 0.5 : std::clamp(gu / (gu - gw), 0.0, 1.0);
    return pu + lambda * (pw - pu);
  }

  // Where triangle t's plane meets the bisectors of cells a, b and of cells c, d.
  Point triangle_cut(std::uint32_t t, CellId a, CellId b, CellId c, CellId d) const {
    const Triangle& tri = domain_.triangles[t];
    const Point& o = domain_.vertices[tri[0]];
    const Point ab = sites_[b] - sites_[a], cd = sites_[d] - sites_[c];
    Eigen::Matrix3d m;
    m.row(0) = (domain_.vertices[tri[1]] - o).cross(domain_.vertices[tri[2]] - o).transpose();
    m.row(1) = ab.transpose();
    m.row(2) = cd.transpose();
    const Eigen::Vector3d rhs(0, ab.dot((sites_[a] + sites_[b]) / 2 - o), cd.dot((sites_[c] + sites_[d]) / 2 - o));
    return o + m.fullPivLu().solve(rhs);
  }

  // Where the edge leaving `a` meets the bisector of c and x: on an input edge, on a bisector of
  // c's own diagram, or on one of the other material's.
  Corner cut(const Corner& a, CellId c, CellId x, std::uint32_t t) const {
    const CellId lo = std::min(c, x), hi = std::max(c, x);
    if (!a.out.bisector) {
      return {Key{KeyKind::EdgeCut, {a.out.a, a.out.b, lo, hi, 0}}, edge_cut(a.out.a, a.out.b, lo, hi), a.out};
    }
    if (a.out.a != c) {
      std::array<CellId, 2> p{std::min(a.out.a, a.out.b), std::max(a.out.a, a.out.b)}, q{lo, hi};
      if (q < p) std::swap(p, q);
      return {Key{KeyKind::InterfaceCut, {t, p[0], p[1], q[0], q[1]}}, triangle_cut(t, p[0], p[1], q[0], q[1]), a.out};
    }
    std::array<CellId, 3> cells{a.out.a, a.out.b, x};
    std::sort(cells.begin(), cells.end());
    return {Key{KeyKind::TriangleCut, {t, cells[0], cells[1], cells[2], 0}},
            triangle_cut(t, cells[0], cells[1], cells[0], cells[2]), a.out};
  }

  // Sutherland-Hodgman: the part of `polygon` nearer c's seed than x's.
  Polygon clip(const Polygon& polygon, CellId c, CellId x, std::uint32_t t) const {
    const std::size_t n = polygon.size();
    std::array<int, 64> small_sides{};
    std::vector<int> large_sides;
    int* sides = small_sides.data();
    if (n > small_sides.size()) {
      large_sides.resize(n);
      sides = large_sides.data();
    }
    bool any_out = false, any_in = false;
    for (std::size_t k = 0; k < n; ++k) {
      sides[k] = side(polygon[k], c, x);
      any_out |= sides[k] > 0;
      any_in |= sides[k] < 0;
    }
    if (!any_out) return polygon;
    if (!any_in) return {};
    const Support along{true, c, x};
    Polygon out;
    out.reserve(n + 2);
    for (std::size_t k = 0; k < n; ++k) {
      const Corner& a = polygon[k];
      const int sa = sides[k], sb = sides[(k + 1) % n];
      if (sa <= 0 && sb <= 0) {
        out.push_back(a);
      } else if (sa < 0) {  // leaving: the cut starts an edge along the bisector
        out.push_back(a);
        Corner x_point = cut(a, c, x, t);
        x_point.out = along;
        out.push_back(x_point);
      } else if (sa == 0) {
        out.push_back({a.key, a.p, along});
      } else if (sb < 0) {  // entering
        out.push_back(cut(a, c, x, t));
      }
    }
    // Corners the bisector passes through exactly may repeat.
    std::vector<Corner> unique;
    unique.reserve(out.size());
    for (const Corner& k : out) {
      if (unique.empty() || unique.back().key != k.key) unique.push_back(k);
    }
    while (unique.size() > 1 && unique.front().key == unique.back().key) unique.pop_back();
    if (unique.size() < 3) unique.clear();
    return unique;
  }

  const SurfaceMesh& domain_;
  std::vector<Point> sites_;
  std::map<std::int32_t, std::unique_ptr<Diagram>> diagrams_;
  std::vector<std::vector<CellId>> neighbours_;
  struct Plane {
    Point normal;  // out of the cell
    double offset = 0;
  };
  std::vector<std::vector<Plane>> beyond_;  // each cell's faces toward outside seeds
};

// Whether a triangle's pieces make up its whole area (to 1e-9): no part of it lies in a cell the
// walk over material cells cannot reach (on an interface, in either material's diagram).
bool covered(const SurfaceMesh& domain, std::uint32_t t, const std::vector<Piece>& pieces) {
  const auto area = [](const Point& normal, const auto& points) {
    Point sum = Point::Zero();
    for (std::size_t k = 0; k < points.size(); ++k) sum += points[k].cross(points[(k + 1) % points.size()]);
    return sum.dot(normal) / 2;
  };
  const Triangle& tri = domain.triangles[t];
  const std::array<Point, 3> corners{domain.vertices[tri[0]], domain.vertices[tri[1]], domain.vertices[tri[2]]};
  const Point normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]).normalized();
  double parts = 0;
  for (const Piece& piece : pieces) {
    if (piece.mirror) continue;
    std::vector<Point> points;
    for (const Corner& k : piece.corners) points.push_back(k.p - corners[0]);
    parts += area(normal, points);
  }
  const std::array<Point, 3> local{Point::Zero(), corners[1] - corners[0], corners[2] - corners[0]};
  const double whole = area(normal, local);
  const double longest =
      std::max({local[1].squaredNorm(), local[2].squaredNorm(), (local[2] - local[1]).squaredNorm()});
  return std::abs(parts - whole) <= 1e-9 * whole + 1e-12 * longest;
}

// Where an interface meets the rest of the surface, an input edge is cut by both materials'
// bisectors on the interface's side and by one material's on the other: every piece's part of an
// input edge gets every cut on it, so that the faces along the edge share their points.
void insert_edge_cuts(const SurfaceMesh& domain, std::vector<Piece>& pieces) {
  std::unordered_map<std::uint64_t, std::vector<std::pair<double, Corner>>> cuts;
  const auto along = [&](std::uint32_t u, std::uint32_t w, const Point& p) {
    return (p - domain.vertices[u]).dot(domain.vertices[w] - domain.vertices[u]);
  };
  for (const Piece& piece : pieces) {
    for (const Corner& k : piece.corners) {
      if (k.key.kind == KeyKind::EdgeCut) {
        cuts[pair_key(k.key.ids[0], k.key.ids[1])].emplace_back(along(k.key.ids[0], k.key.ids[1], k.p), k);
      }
    }
  }
  for (auto& [edge, on_edge] : cuts) {
    std::sort(on_edge.begin(), on_edge.end(), [](const auto& x, const auto& y) {
      return std::pair(x.first, x.second.key) < std::pair(y.first, y.second.key);
    });
    on_edge.erase(std::unique(on_edge.begin(), on_edge.end(),
                              [](const auto& x, const auto& y) { return x.second.key == y.second.key; }),
                  on_edge.end());
  }
  for (Piece& piece : pieces) {
    Polygon polygon;
    const std::size_t n = piece.corners.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Corner& a = piece.corners[k];
      const Corner& b = piece.corners[(k + 1) % n];
      polygon.push_back(a);
      if (a.out.bisector) continue;
      const auto it = cuts.find(pair_key(a.out.a, a.out.b));
      if (it == cuts.end()) continue;
      const double from = along(a.out.a, a.out.b, a.p), to = along(a.out.a, a.out.b, b.p);
      const auto between = [&](const std::pair<double, Corner>& c) {
        return std::min(from, to) < c.first && c.first < std::max(from, to) && c.second.key != a.key &&
               c.second.key != b.key;
      };
      const auto insert = [&](const std::pair<double, Corner>& c) {
        if (between(c)) polygon.push_back({c.second.key, c.second.p, a.out});
      };
      if (from < to) {
        std::for_each(it->second.begin(), it->second.end(), insert);
      } else {
        std::for_each(it->second.rbegin(), it->second.rend(), insert);
      }
    }
    piece.corners = std::move(polygon);
  }
}

enum class Side : std::int8_t { Unknown, Inside, Outside };

// The clipped mesh, assembled from the pieces: every face between cells cut along the surface's
// trace on it, every piece a boundary face of its cell.
class Assembly {
 public:
  Assembly(const VoronoiMesh& voronoi, const SurfaceMesh& domain) : voronoi_(voronoi), domain_(domain) {}

  VoronoiMesh run(std::vector<Piece> pieces, ClippingStats& stats) {
    number_points(pieces);
    collect_crossings(pieces);
    classify_points();
    collect_traces(pieces);
    VoronoiMesh out;
    out.region_names = voronoi_.region_names;
    out.points = voronoi_.points;
    out.points.insert(out.points.end(), new_points_.begin(), new_points_.end());
    std::sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) {
      return std::tuple(a.cell, a.triangle, a.across) < std::tuple(b.cell, b.triangle, b.across);
    });
    // Each cell's faces (those it owns, then its pieces of the surface) on all threads, then
    // concatenated in cell order: the mesh does not depend on the threads.
    const std::size_t cells = voronoi_.cells.size();
    std::vector<std::size_t> first_face(cells + 1, voronoi_.faces.size()), first_piece(cells + 1, pieces.size());
    for (std::size_t f = voronoi_.faces.size(); f-- > 0;)
      first_face[static_cast<std::size_t>(voronoi_.faces[f].owner)] = f;
    for (std::size_t p = pieces.size(); p-- > 0;) first_piece[pieces[p].cell] = p;
    for (std::size_t c = cells; c-- > 0;) {
      first_face[c] = std::min(first_face[c], first_face[c + 1]);
      first_piece[c] = std::min(first_piece[c], first_piece[c + 1]);
    }
    std::vector<std::vector<VoronoiFace>> faces_of(cells);
    std::vector<ClippingStats> stats_of(cells);
    tbb::parallel_for(std::size_t{0}, cells, [&](std::size_t c) {
      bool clipped = false;
      for (std::size_t f = first_face[c]; f < first_face[c + 1]; ++f) clipped |= emit_face(f, faces_of[c], stats_of[c]);
      if (first_piece[c + 1] > first_piece[c]) {
        emit_surface(std::span(pieces).subspan(first_piece[c], first_piece[c + 1] - first_piece[c]), faces_of[c],
                     stats_of[c]);
        clipped = true;
      }
      stats_of[c].clipped_cells = clipped;
    });
    for (std::size_t c = 0; c < cells; ++c) {
      std::move(faces_of[c].begin(), faces_of[c].end(), std::back_inserter(out.faces));
      faces_of[c] = {};
      stats.clipped_cells += stats_of[c].clipped_cells;
      stats.surface_pieces += stats_of[c].surface_pieces;
      stats.clipped_faces += stats_of[c].clipped_faces;
      stats.dropped_faces += stats_of[c].dropped_faces;
      stats.holes += stats_of[c].holes;
    }
    out.cells.resize(voronoi_.cells.size());
    for (std::size_t c = 0; c < out.cells.size(); ++c) {
      const VoronoiCell& in = voronoi_.cells[c];
      out.cells[c].seed = in.seed;
      out.cells[c].site = in.site;
      out.cells[c].seed_kind = in.seed_kind;
      out.cells[c].region = in.region;
    }
    for (std::size_t f = 0; f < out.faces.size(); ++f) {
      out.cells[static_cast<std::size_t>(out.faces[f].owner)].faces.push_back(static_cast<Index>(f));
      if (out.faces[f].neighbour != kNoCell) {
        out.cells[static_cast<std::size_t>(out.faces[f].neighbour)].faces.push_back(static_cast<Index>(f));
      }
    }
    for (std::size_t c = 0; c < out.cells.size(); ++c) {
      if (out.cells[c].faces.empty()) {
        throw Error(Error::Kind::Internal, c_format("the clipped cell of seed %u has no face", out.cells[c].seed));
      }
    }
    cells::renumber_points(out);
    geometry::measure_cells(out);
    return out;
  }

 private:
  std::int32_t material_of(CellId c) const { return voronoi_.cells[c].region; }

  // Whether the triangle's normal (right-hand rule) points out of the material.
  bool faces_out(std::uint32_t t, std::int32_t material) const { return domain_.face_regions[t].back == material; }

  Point outward_normal(std::uint32_t t, std::int32_t material) const {
    const Triangle& tri = domain_.triangles[t];
    const Point n = (domain_.vertices[tri[1]] - domain_.vertices[tri[0]])
                        .cross(domain_.vertices[tri[2]] - domain_.vertices[tri[0]]);
    return faces_out(t, material) ? n : Point(-n);
  }

  // The new points, after the Voronoi vertices, in the order of their keys.
  void number_points(const std::vector<Piece>& pieces) {
    for (const Piece& piece : pieces) {
      for (const Corner& k : piece.corners) keys_.emplace_back(k.key, k.p);
    }
    std::sort(keys_.begin(), keys_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    keys_.erase(
        std::unique(keys_.begin(), keys_.end(), [](const auto& a, const auto& b) { return a.first == b.first; }),
        keys_.end());
    new_points_.reserve(keys_.size());
    for (const auto& [key, p] : keys_) new_points_.push_back(p);
  }

  Index point_of(const Key& key) const {
    const auto it =
        std::lower_bound(keys_.begin(), keys_.end(), key, [](const auto& a, const Key& k) { return a.first < k; });
    const auto p = static_cast<Index>(voronoi_.points.size() + static_cast<std::size_t>(it - keys_.begin()));
    const auto alias = alias_.find(p);
    return alias == alias_.end() ? p : alias->second;
  }

  const Point& point(Index p) const {
    return p < voronoi_.points.size() ? voronoi_.points[p] : new_points_[p - voronoi_.points.size()];
  }

  void collect_crossings(const std::vector<Piece>& pieces) {
    for (const Piece& piece : pieces) {
      for (const Corner& k : piece.corners) {
        if (k.key.kind == KeyKind::TriangleCut) {
          crossings_.push_back({{k.key.ids[1], k.key.ids[2], k.key.ids[3]}, point_of(k.key), k.key.ids[0]});
        }
      }
    }
    std::sort(crossings_.begin(), crossings_.end());
    crossings_.erase(std::unique(crossings_.begin(), crossings_.end()), crossings_.end());
    // The cells about each Voronoi edge, from the faces that have it.
    std::vector<std::pair<std::uint64_t, std::int32_t>> edge_cells;
    for (const VoronoiFace& f : voronoi_.faces) {
      for (std::size_t k = 0; k < f.points.size(); ++k) {
        const std::uint64_t e = pair_key(f.points[k], f.points[(k + 1) % f.points.size()]);
        edge_cells.emplace_back(e, f.owner);
        edge_cells.emplace_back(e, f.neighbour);
      }
    }
    std::sort(edge_cells.begin(), edge_cells.end());
    edge_cells.erase(std::unique(edge_cells.begin(), edge_cells.end()), edge_cells.end());
    for (std::size_t i = 0; i < edge_cells.size();) {
      std::size_t j = i;
      std::vector<CellId> around;
      for (; j < edge_cells.size() && edge_cells[j].first == edge_cells[i].first; ++j) {
        if (edge_cells[j].second != kNoCell) around.push_back(static_cast<CellId>(edge_cells[j].second));
      }
      edges_.push_back(edge_cells[i].first);
      add_edge_crossings(edge_cells[i].first, around);
      i = j;
    }
  }

  // The crossings on the Voronoi edge `e`, ordered from its lower point to its higher.
  void add_edge_crossings(std::uint64_t e, const std::vector<CellId>& around) {
    std::vector<std::pair<double, Crossing>> on_edge;
    const auto a = static_cast<Index>(e >> 32), b = static_cast<Index>(e & 0xffffffffu);
    const Point d = point(b) - point(a);
    for (std::size_t i = 0; i < around.size(); ++i) {
      for (std::size_t j = i + 1; j < around.size(); ++j) {
        for (std::size_t k = j + 1; k < around.size(); ++k) {
          std::array<CellId, 3> cells{around[i], around[j], around[k]};
          std::sort(cells.begin(), cells.end());
          const auto lo = std::lower_bound(crossings_.begin(), crossings_.end(), Crossing{cells, 0, 0});
          for (auto it = lo; it != crossings_.end() && it->cells == cells; ++it) {
            on_edge.emplace_back((point(it->point) - point(a)).dot(d), *it);
          }
        }
      }
    }
    if (on_edge.empty()) return;
    // A triangle meets a Voronoi edge once. Where four or more cells share the edge (a lattice's
    // seeds), each cell names the point by the triple it sees: they are one point.
    std::sort(on_edge.begin(), on_edge.end(), [](const auto& x, const auto& y) {
      return std::pair(x.second.triangle, x.second.point) < std::pair(y.second.triangle, y.second.point);
    });
    std::vector<std::pair<double, Crossing>> unique;
    for (const auto& c : on_edge) {
      if (!unique.empty() && unique.back().second.triangle == c.second.triangle) {
        alias_[c.second.point] = unique.back().second.point;
      } else {
        unique.push_back(c);
      }
    }
    std::sort(unique.begin(), unique.end(), [](const auto& x, const auto& y) {
      return std::pair(x.first, x.second.point) < std::pair(y.first, y.second.point);
    });
    std::vector<Crossing> sorted;
    for (const auto& [t, c] : unique) sorted.push_back(c);
    edge_crossings_.emplace(e, std::move(sorted));
  }

  // Inside or outside the material, for every Voronoi vertex: at the ends of an edge the surface
  // crosses, from the direction it crosses (the surface's outward normal against the edge's);
  // along edges it does not cross, the same as their other end.
  void classify_points() {
    const std::size_t n = voronoi_.points.size();
    side_.assign(n, Side::Unknown);
    const auto set = [&](Index p, Side s) {
      if (side_[p] != Side::Unknown && side_[p] != s) {
        throw Error(Error::Kind::Internal,
                    c_format("the surface's crossings disagree on which side of it Voronoi vertex %s lies",
                             describe_point(point(p)).c_str()));
      }
      side_[p] = s;
    };
    std::vector<std::vector<Index>> adjacent(n);
    for (std::uint64_t e : edges_) {
      const auto a = static_cast<Index>(e >> 32), b = static_cast<Index>(e & 0xffffffffu);
      const auto it = edge_crossings_.find(e);
      if (it == edge_crossings_.end()) {
        adjacent[a].push_back(b);
        adjacent[b].push_back(a);
        continue;
      }
      const Point d = point(b) - point(a);
      bool exits = false;
      for (std::size_t k = 0; k < it->second.size(); ++k) {
        const Crossing& crossing = it->second[k];
        const bool out = outward_normal(crossing.triangle, material_of(crossing.cells[0])).dot(d) > 0;
        if (k > 0 && out == exits) {
          throw Error(Error::Kind::Internal, c_format("the surface enters a Voronoi edge twice in a row near %s",
                                                      describe_point(point(it->second[k].point)).c_str()));
        }
        exits = out;
        if (k == 0) set(a, out ? Side::Inside : Side::Outside);
      }
      set(b, exits ? Side::Outside : Side::Inside);
    }
    std::vector<Index> stack;
    for (Index p = 0; p < n; ++p) {
      if (side_[p] != Side::Unknown) stack.push_back(p);
    }
    while (!stack.empty()) {
      const Index p = stack.back();
      stack.pop_back();
      for (Index q : adjacent[p]) {
        if (side_[q] == Side::Unknown) {
          side_[q] = side_[p];
          stack.push_back(q);
        }
      }
    }
    // No crossing at all (the surface inside one cell): a ray decides.
    if (std::find(side_.begin(), side_.end(), Side::Unknown) == side_.end()) return;
    const RegionLocator locate(domain_);
    std::vector<std::int32_t> material(n, kNoCell);
    for (const VoronoiFace& f : voronoi_.faces) {
      for (Index p : f.points) material[p] = material_of(static_cast<CellId>(f.owner));
    }
    for (Index p = 0; p < n; ++p) {
      if (side_[p] == Side::Unknown) {
        side_[p] = locate.region_of(point(p)) == material[p] ? Side::Inside : Side::Outside;
      }
    }
  }

  // The surface's trace on each face between cells, from the pieces of the face's owner: each
  // boundary edge of a piece along the bisector, in the direction the face runs about its normal.
  void collect_traces(const std::vector<Piece>& pieces) {
    std::unordered_map<std::uint64_t, std::size_t> face_of;
    for (std::size_t f = 0; f < voronoi_.faces.size(); ++f) {
      const VoronoiFace& face = voronoi_.faces[f];
      if (face.neighbour != kNoCell) {
        face_of.emplace(pair_key(static_cast<CellId>(face.owner), static_cast<CellId>(face.neighbour)), f);
      }
    }
    for (const Piece& piece : pieces) {
      const std::size_t n = piece.corners.size();
      for (std::size_t k = 0; k < n; ++k) {
        const Corner& a = piece.corners[k];
        if (!a.out.bisector) continue;
        const auto it = face_of.find(pair_key(a.out.a, a.out.b));
        if (it == face_of.end() || voronoi_.faces[it->second].owner != static_cast<std::int32_t>(piece.cell)) continue;
        Index from = point_of(a.key), to = point_of(piece.corners[(k + 1) % n].key);
        // The piece runs about the surface's outward normal; the face, about the normal out of
        // its owner, meets it along this edge in the other direction.
        if (faces_out(piece.triangle, material_of(piece.cell))) std::swap(from, to);
        traces_[it->second].emplace_back(from, to);
      }
    }
  }

  // The part of face f inside the material, as one face per connected part. Returns whether the
  // surface crosses it.
  bool emit_face(std::size_t f, std::vector<VoronoiFace>& out, ClippingStats& stats) const {
    const VoronoiFace& face = voronoi_.faces[f];
    const auto trace = traces_.find(f);
    std::vector<std::pair<Index, Index>> segments;
    if (trace != traces_.end()) segments = trace->second;
    bool crossed = !segments.empty();
    const std::size_t n = face.points.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Index a = face.points[k], b = face.points[(k + 1) % n];
      const auto it = edge_crossings_.find(pair_key(a, b));
      if (it == edge_crossings_.end()) {
        if (side_[a] == Side::Inside) segments.emplace_back(a, b);
        continue;
      }
      crossed = true;
      std::vector<Index> along{a};
      const auto add = [&](const Crossing& c) { along.push_back(c.point); };
      if (a < b) {
        std::for_each(it->second.begin(), it->second.end(), add);
      } else {
        std::for_each(it->second.rbegin(), it->second.rend(), add);
      }
      along.push_back(b);
      bool inside = side_[a] == Side::Inside;
      for (std::size_t i = 0; i + 1 < along.size(); ++i, inside = !inside) {
        if (inside) segments.emplace_back(along[i], along[i + 1]);
      }
    }
    if (face.neighbour == kNoCell) {
      if (!segments.empty()) {
        throw Error(Error::Kind::InvalidGeometry,
                    c_format("the seeds do not cover the material: the cell of seed %u reaches its boundary at %s "
                             "beyond the other seeds",
                             face.owner_seed, describe_point(point(face.points.front())).c_str()));
      }
      return false;
    }
    if (!crossed) {
      if (side_[face.points.front()] == Side::Inside) {
        out.push_back(face);
      } else {
        ++stats.dropped_faces;
      }
      return false;
    }
    ++stats.clipped_faces;
    std::vector<Loop> loops = trace_loops(segments, face);
    const Point normal = area_vector(face.points);
    stats.holes += static_cast<std::size_t>(
        std::count_if(loops.begin(), loops.end(), [&](const Loop& loop) { return area_vector(loop).dot(normal) < 0; }));
    loops = simple_polygons(
        std::move(loops), [&](Index p) -> const Point& { return point(p); }, normal);
    for (std::vector<Index>& loop : loops) {
      VoronoiFace part = face;
      part.points = std::move(loop);
      out.push_back(std::move(part));
    }
    return true;
  }

  Point area_vector(const std::vector<Index>& polygon) const {
    Point sum = Point::Zero();
    const Point& o = point(polygon.front());
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
      sum += (point(polygon[k]) - o).cross(point(polygon[k + 1]) - o);
    }
    return sum / 2;
  }

  std::vector<std::vector<Index>> trace_loops(std::vector<std::pair<Index, Index>>& segments,
                                              const VoronoiFace& face) const {
    std::sort(segments.begin(), segments.end());
    segments.erase(std::unique(segments.begin(), segments.end()), segments.end());
    const auto broken = [&](const char* what) {
      return Error(
          Error::Kind::Internal,
          c_format("the part of the face between the cells of seeds %u and %u inside the material %s near %s",
                   face.owner_seed, face.neighbour_seed, what, describe_point(point(face.points.front())).c_str()));
    };
    std::vector<char> used(segments.size(), 0);
    std::vector<std::vector<Index>> loops;
    for (std::size_t s = 0; s < segments.size(); ++s) {
      if (used[s]) continue;
      std::vector<Index> loop;
      std::size_t at = s;
      while (!used[at]) {
        used[at] = 1;
        loop.push_back(segments[at].first);
        const Index next = segments[at].second;
        const auto it = std::lower_bound(segments.begin(), segments.end(), std::pair(next, Index{0}));
        if (it == segments.end() || it->first != next) throw broken("does not close");
        if (it + 1 != segments.end() && (it + 1)->first == next) throw broken("branches");
        at = static_cast<std::size_t>(it - segments.begin());
      }
      if (at != s) throw broken("does not close");
      if (loop.size() >= 3) loops.push_back(std::move(loop));
    }
    return loops;
  }

  std::vector<Index> outward_polygon(const Piece& piece) const {
    std::vector<Index> polygon;
    polygon.reserve(piece.corners.size());
    for (const Corner& k : piece.corners) polygon.push_back(point_of(k.key));
    if (!faces_out(piece.triangle, material_of(piece.cell))) std::reverse(polygon.begin(), polygon.end());
    return polygon;
  }

  Point unit_normal(const Piece& p) const { return outward_normal(p.triangle, material_of(p.cell)).normalized(); }

  // Two pieces of one cell side by side lie in one plane of one part of the input: triangles of
  // one group, with the same regions, whose normals differ by less than 1e-12 radians, and the
  // same cell across. A looser bound would join a scan's nearly flat triangles into faces that
  // leave the input (by the angle times the face's size), and their volume with it.
  bool flat_together(const Piece& p, const Piece& q) const {
    const std::uint32_t s = p.triangle, t = q.triangle;
    const Point a = unit_normal(p), b = unit_normal(q);
    return p.across == q.across && domain_.face_group[s] == domain_.face_group[t] &&
           domain_.face_regions[s] == domain_.face_regions[t] && a.dot(b) > 0 && a.cross(b).norm() < 1e-12;
  }

  // A cell's faces on the surface: its pieces, those side by side in one plane joined into one
  // face, so that a flat side of a CAD model that crosses a cell is one face of it, not one per
  // triangle. A piece on an interface is a face toward the cell across, listed by the lower cell.
  void emit_surface(std::span<const Piece> all, std::vector<VoronoiFace>& out, ClippingStats& stats) const {
    std::vector<Piece> pieces;
    for (const Piece& p : all) {
      if (p.across == kNoneAcross || p.cell < p.across) pieces.push_back(p);
    }
    stats.surface_pieces += pieces.size();
    std::vector<std::vector<Index>> polygons;
    for (const Piece& p : pieces) polygons.push_back(outward_polygon(p));
    std::map<std::pair<Index, Index>, std::uint32_t> edge_of;
    for (std::uint32_t i = 0; i < polygons.size(); ++i) {
      for (std::size_t k = 0; k < polygons[i].size(); ++k) {
        edge_of.emplace(std::pair(polygons[i][k], polygons[i][(k + 1) % polygons[i].size()]), i);
      }
    }
    UnionFind together(polygons.size());
    for (const auto& [edge, i] : edge_of) {
      const auto twin = edge_of.find({edge.second, edge.first});
      if (twin != edge_of.end() && flat_together(pieces[i], pieces[twin->second])) {
        together.unite(i, twin->second);
      }
    }
    std::map<std::uint32_t, std::vector<std::uint32_t>> groups;
    for (std::uint32_t i = 0; i < polygons.size(); ++i) groups[together.find(i)].push_back(i);
    for (const auto& [root, members] : groups) {
      std::vector<std::vector<Index>> faces;
      if (members.size() > 1) faces = joined(polygons, members, unit_normal(pieces[root]));
      if (faces.empty()) {
        for (std::uint32_t i : members) faces.push_back(polygons[i]);
      }
      for (std::vector<Index>& f : faces) {
        VoronoiFace face;
        face.points = std::move(f);
        const Piece& piece = pieces[root];
        const std::int32_t material = material_of(piece.cell);
        face.owner = static_cast<std::int32_t>(piece.cell);
        face.owner_seed = face.neighbour_seed = voronoi_.cells[piece.cell].seed;
        if (piece.across != kNoneAcross) {
          face.neighbour = static_cast<std::int32_t>(piece.across);
          face.neighbour_seed = voronoi_.cells[piece.across].seed;
        }
        const RegionPair& sides = domain_.face_regions[piece.triangle];
        face.regions = {material, sides.back == material ? sides.front : sides.back};
        out.push_back(std::move(face));
      }
    }
  }

  // The outline of the polygons `members` side by side: the edges not shared between two of them,
  // traced into loops, holes cut out. Empty where the outline touches itself at a point.
  std::vector<std::vector<Index>> joined(const std::vector<std::vector<Index>>& polygons,
                                         const std::vector<std::uint32_t>& members, const Point& normal) const {
    std::set<std::pair<Index, Index>> edges;
    for (std::uint32_t i : members) {
      for (std::size_t k = 0; k < polygons[i].size(); ++k) {
        const std::pair e(polygons[i][k], polygons[i][(k + 1) % polygons[i].size()]);
        if (!edges.erase({e.second, e.first})) edges.insert(e);
      }
    }
    std::map<Index, Index> next;
    for (const auto& [a, b] : edges) {
      if (!next.emplace(a, b).second) return {};
    }
    std::vector<Loop> loops;
    while (!next.empty()) {
      Loop loop;
      Index at = next.begin()->first;
      while (true) {
        const auto it = next.find(at);
        if (it == next.end()) break;
        loop.push_back(at);
        at = it->second;
        next.erase(it);
      }
      if (at != loop.front()) return {};
      loops.push_back(std::move(loop));
    }
    return simple_polygons(
        std::move(loops), [&](Index p) -> const Point& { return point(p); }, normal);
  }

  const VoronoiMesh& voronoi_;
  const SurfaceMesh& domain_;
  std::vector<std::pair<Key, Point>> keys_;
  std::vector<Point> new_points_;
  std::vector<Crossing> crossings_;
  std::unordered_map<Index, Index> alias_;  // a crossing's other names: one point, several keys
  std::vector<std::uint64_t> edges_;
  std::unordered_map<std::uint64_t, std::vector<Crossing>> edge_crossings_;
  std::vector<Side> side_;
  std::unordered_map<std::size_t, std::vector<std::pair<Index, Index>>> traces_;
};

}  // namespace

VoronoiMesh material_diagrams(const std::vector<Seed>& seeds, std::size_t materials_end, int threads) {
  VoronoiMesh all;
  const std::vector<Seed> outside(seeds.begin() + static_cast<std::ptrdiff_t>(materials_end), seeds.end());
  for (std::size_t first = 0; first < materials_end;) {
    const std::int32_t material = seeds[first].region;
    std::size_t end = first;
    while (end < materials_end && seeds[end].region == material) ++end;
    std::vector<Seed> own(seeds.begin() + static_cast<std::ptrdiff_t>(first),
                          seeds.begin() + static_cast<std::ptrdiff_t>(end));
    own.insert(own.end(), outside.begin(), outside.end());
    const VoronoiMesh diagram = compute_cells(own, {.materials = {material}, .threads = threads});
    const auto seed_of = [&](Index s) {
      return static_cast<Index>(s < end - first ? first + s : materials_end + (s - (end - first)));
    };
    const auto cell_of = [&](std::int32_t c) { return c == kNoCell ? c : static_cast<std::int32_t>(first) + c; };
    const auto point_base = static_cast<Index>(all.points.size());
    const auto face_base = static_cast<Index>(all.faces.size());
    all.points.insert(all.points.end(), diagram.points.begin(), diagram.points.end());
    for (VoronoiFace f : diagram.faces) {
      for (Index& p : f.points) p += point_base;
      f.owner = cell_of(f.owner);
      f.neighbour = cell_of(f.neighbour);
      f.owner_seed = seed_of(f.owner_seed);
      f.neighbour_seed = seed_of(f.neighbour_seed);
      all.faces.push_back(std::move(f));
    }
    for (VoronoiCell c : diagram.cells) {
      c.seed = seed_of(c.seed);
      for (Index& f : c.faces) f += face_base;
      all.cells.push_back(std::move(c));
    }
    first = end;
  }
  return all;
}

VoronoiMesh clip_cells(const VoronoiMesh& voronoi, const SurfaceMesh& domain, ClippingStats* stats) {
  if (!domain.has_regions()) {
    throw Error(Error::Kind::Internal, "clip_cells needs the domain's regions (label_regions)");
  }
  const RestrictedCells restricted(voronoi, domain);
  std::vector<std::uint32_t> boundary;
  bool interfaces = false;
  for (std::uint32_t t = 0; t < domain.num_faces(); ++t) {
    const RegionPair& r = domain.face_regions[t];
    if (r.back == r.front || !(restricted.meshes(r.back) || restricted.meshes(r.front))) continue;
    boundary.push_back(t);
    interfaces |= restricted.meshes(r.back) && restricted.meshes(r.front);
  }
  std::vector<std::vector<Piece>> per_triangle(boundary.size());
  std::vector<char> uncovered(boundary.size(), 0);
  tbb::parallel_for(std::size_t{0}, boundary.size(), [&](std::size_t i) {
    std::optional<std::vector<Piece>> pieces = restricted.pieces(boundary[i]);
    uncovered[i] = !pieces || !covered(domain, boundary[i], *pieces);
    if (pieces) per_triangle[i] = std::move(*pieces);
  });
  ClippingStats local;
  ClippingStats& figures = stats ? *stats : local;
  figures.uncovered_triangles += static_cast<std::size_t>(std::count(uncovered.begin(), uncovered.end(), 1));
  if (figures.uncovered_triangles) return {};
  std::vector<Piece> pieces;
  for (std::vector<Piece>& p : per_triangle) {
    std::move(p.begin(), p.end(), std::back_inserter(pieces));
    p = {};
  }
  if (interfaces) insert_edge_cuts(domain, pieces);
  return Assembly(voronoi, domain).run(std::move(pieces), figures);
}

}  // namespace vorocrust::clipping
