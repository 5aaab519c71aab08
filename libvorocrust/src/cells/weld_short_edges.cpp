#include "cells/weld_short_edges.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <utility>

#include "cells/renumber_points.hpp"
#include "core/union_find.hpp"
#include "geometry/measure_cells.hpp"

namespace vorocrust::cells {
namespace {

std::uint64_t edge_key(Index a, Index b) { return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b); }

// The least spacing of the cells whose faces have each edge.
std::unordered_map<std::uint64_t, double> edge_spacing(const VoronoiMesh& mesh, const std::vector<double>& spacing) {
  std::unordered_map<std::uint64_t, double> least;
  for (const VoronoiFace& f : mesh.faces) {
    double s = spacing[static_cast<std::size_t>(f.owner)];
    if (f.neighbour != kNoCell) s = std::min(s, spacing[static_cast<std::size_t>(f.neighbour)]);
    for (std::size_t k = 0; k < f.points.size(); ++k) {
      const auto [it, added] = least.emplace(edge_key(f.points[k], f.points[(k + 1) % f.points.size()]), s);
      if (!added) it->second = std::min(it->second, s);
    }
  }
  return least;
}

// The face's points once each, in order, with every point replaced by its chain's.
std::vector<Index> welded(const std::vector<Index>& face, const std::vector<Index>& into) {
  std::vector<Index> out;
  for (Index p : face) {
    const Index q = into[p];
    if (out.empty() || out.back() != q) out.push_back(q);
  }
  while (out.size() > 1 && out.front() == out.back()) out.pop_back();
  return out;
}

// Whether cell c, its points welded, still has each edge once in each direction: a chain that
// joins two of its points no edge of its own joins would pinch it.
bool closed(const VoronoiMesh& mesh, std::size_t c, const std::vector<Index>& into) {
  const VoronoiCell& cell = mesh.cells[c];
  const bool touched = std::any_of(cell.faces.begin(), cell.faces.end(), [&](Index f) {
    const std::vector<Index>& points = mesh.faces[f].points;
    return std::any_of(points.begin(), points.end(), [&](Index p) { return into[p] != p; });
  });
  if (!touched) return true;
  std::vector<std::pair<Index, Index>> edges;
  for (Index f : cell.faces) {
    std::vector<Index> w = welded(mesh.faces[f].points, into);
    if (w.size() < 3) continue;
    if (mesh.faces[f].owner != static_cast<std::int32_t>(c)) std::reverse(w.begin(), w.end());
    for (std::size_t k = 0; k < w.size(); ++k) edges.emplace_back(w[k], w[(k + 1) % w.size()]);
  }
  std::sort(edges.begin(), edges.end());
  if (std::adjacent_find(edges.begin(), edges.end()) != edges.end()) return false;
  return std::all_of(edges.begin(), edges.end(), [&](const auto& e) {
    return std::binary_search(edges.begin(), edges.end(), std::pair(e.second, e.first));
  });
}

bool pinched(std::vector<Index> polygon) {
  std::sort(polygon.begin(), polygon.end());
  return std::adjacent_find(polygon.begin(), polygon.end()) != polygon.end();
}

double non_planarity(const VoronoiMesh& mesh, const std::vector<Index>& face) {
  Point mean = Point::Zero(), normal = Point::Zero();
  for (std::size_t k = 0; k < face.size(); ++k) {
    const Point& a = mesh.points[face[k]];
    const Point& b = mesh.points[face[(k + 1) % face.size()]];
    mean += a;
    normal +=
        Point((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()), (a.x() - b.x()) * (a.y() + b.y()));
  }
  mean /= static_cast<double>(face.size());
  if (normal.norm() == 0) return 0;
  normal.normalize();
  double off = 0, diameter = 0;
  for (std::size_t i = 0; i < face.size(); ++i) {
    off = std::max(off, std::abs((mesh.points[face[i]] - mean).dot(normal)));
    for (std::size_t j = i + 1; j < face.size(); ++j) {
      diameter = std::max(diameter, (mesh.points[face[i]] - mesh.points[face[j]]).norm());
    }
  }
  return diameter > 0 ? off / diameter : 0;
}

// One round: the chains of the edges short now welded.
WeldStats weld_once(VoronoiMesh& mesh, const std::vector<double>& spacing, double fraction) {
  WeldStats stats;
  const std::size_t n = mesh.points.size();
  std::vector<std::uint64_t> short_edges;
  double shortest = std::numeric_limits<double>::infinity();
  for (const auto& [e, s] : edge_spacing(mesh, spacing)) {
    const double length = (mesh.points[e >> 32] - mesh.points[e & 0xffffffffu]).norm();
    shortest = std::min(shortest, length / s);
    if (length < fraction * s) short_edges.push_back(e);
  }
  std::sort(short_edges.begin(), short_edges.end());
  stats.short_edges = short_edges.size();
  stats.shortest_edge_before = stats.shortest_edge_after = std::isfinite(shortest) ? shortest : 0;
  if (short_edges.empty()) return stats;

  // Chains of short edges; a chain that would pinch a face or flatten a cell is left as it was,
  // and the check runs again, for no chain's release can break another's faces.
  std::vector<char> refused(n, 0);
  std::vector<Index> into(n);
  for (bool settled = false; !settled;) {
    UnionFind chains(n);
    for (std::uint64_t e : short_edges) {
      const auto a = static_cast<Index>(e >> 32), b = static_cast<Index>(e & 0xffffffffu);
      if (!refused[a] && !refused[b]) chains.unite(a, b);
    }
    for (Index p = 0; p < n; ++p) into[p] = static_cast<Index>(chains.find(p));
    settled = true;
    const auto refuse = [&](const std::vector<Index>& points) {
      for (Index p : points) {
        if (into[p] != p ||
            std::any_of(points.begin(), points.end(), [&](Index q) { return q != p && into[q] == p; })) {
          refused[p] = 1;
          settled = false;
        }
      }
    };
    std::vector<int> faces_left(mesh.cells.size(), 0);
    for (const VoronoiFace& f : mesh.faces) {
      const std::vector<Index> w = welded(f.points, into);
      if (w.size() < 3) continue;
      if (pinched(w)) refuse(f.points);
      ++faces_left[static_cast<std::size_t>(f.owner)];
      if (f.neighbour != kNoCell) ++faces_left[static_cast<std::size_t>(f.neighbour)];
    }
    for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
      if (faces_left[c] >= 4 && closed(mesh, c, into)) continue;
      for (Index f : mesh.cells[c].faces) refuse(mesh.faces[f].points);
    }
  }

  // Each chain's point: the mean of its boundary points, or of all.
  std::vector<char> on_boundary(n, 0);
  for (const VoronoiFace& f : mesh.faces) {
    if (f.neighbour == kNoCell) {
      for (Index p : f.points) on_boundary[p] = 1;
    }
  }
  std::vector<Point> total(n, Point::Zero());
  std::vector<int> count(n, 0), boundary_count(n, 0);
  std::vector<Point> boundary_total(n, Point::Zero());
  for (Index p = 0; p < n; ++p) {
    const Index r = into[p];
    total[r] += mesh.points[p];
    ++count[r];
    if (on_boundary[p]) {
      boundary_total[r] += mesh.points[p];
      ++boundary_count[r];
    }
    if (r != p) ++stats.welded_points;
  }
  for (Index r = 0; r < n; ++r) {
    if (count[r] < 2) continue;
    mesh.points[r] = boundary_count[r] ? Point(boundary_total[r] / boundary_count[r]) : Point(total[r] / count[r]);
  }

  // The faces, their welded points in order; those left with fewer than three dropped.
  std::vector<VoronoiFace> faces;
  faces.reserve(mesh.faces.size());
  for (VoronoiFace& f : mesh.faces) {
    std::vector<Index> w = welded(f.points, into);
    if (w.size() < 3) {
      ++stats.dropped_faces;
      continue;
    }
    f.points = std::move(w);
    faces.push_back(std::move(f));
  }
  mesh.faces = std::move(faces);
  for (VoronoiCell& c : mesh.cells) c.faces.clear();
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    mesh.cells[static_cast<std::size_t>(mesh.faces[f].owner)].faces.push_back(static_cast<Index>(f));
    if (mesh.faces[f].neighbour != kNoCell) {
      mesh.cells[static_cast<std::size_t>(mesh.faces[f].neighbour)].faces.push_back(static_cast<Index>(f));
    }
  }
  for (std::uint64_t e : short_edges) stats.kept_edges += into[e >> 32] != into[e & 0xffffffffu];
  renumber_points(mesh);
  return stats;
}

}  // namespace

WeldStats weld_short_edges(VoronoiMesh& mesh, const std::vector<double>& spacing, double fraction) {
  // A welded point moves to its chain's mean, and may come nearer another: rounds go on while
  // they weld something, up to a bound.
  constexpr int kRounds = 8;
  // Planar to rounding: farther from it than this over the face's diameter counts as not.
  constexpr double kPlanar = 1e-12;
  WeldStats stats = weld_once(mesh, spacing, fraction);
  stats.fraction = fraction;
  for (int round = 1; round < kRounds && stats.welded_points > 0; ++round) {
    const WeldStats more = weld_once(mesh, spacing, fraction);
    if (more.welded_points == 0) {
      stats.kept_edges = more.kept_edges;
      break;
    }
    stats.short_edges += more.short_edges;
    stats.welded_points += more.welded_points;
    stats.dropped_faces += more.dropped_faces;
    stats.kept_edges = more.kept_edges;
  }
  // Non-planarity over the faces as they end, a welded point's last position.
  for (const VoronoiFace& f : mesh.faces) {
    if (f.points.size() < 4) continue;
    const double off = non_planarity(mesh, f.points);
    stats.max_non_planarity = std::max(stats.max_non_planarity, off);
    stats.non_planar_faces += off > kPlanar;
  }
  geometry::measure_cells(mesh);
  double shortest = std::numeric_limits<double>::infinity();
  for (const auto& [e, s] : edge_spacing(mesh, spacing)) {
    shortest = std::min(shortest, (mesh.points[e >> 32] - mesh.points[e & 0xffffffffu]).norm() / s);
  }
  stats.shortest_edge_after = std::isfinite(shortest) ? shortest : 0;
  return stats;
}

}  // namespace vorocrust::cells
