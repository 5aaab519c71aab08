#include "clipping/dual_tets.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace vorocrust::clipping {

DualTets dual_tets(const VoronoiMesh& clipped) {
  // Each point's cells, up to five (a fifth only says the point is degenerate), and whether a
  // face of the surface has it.
  const std::size_t n = clipped.points.size();
  std::vector<std::array<std::uint32_t, 5>> around(n);
  std::vector<std::uint8_t> count(n, 0);
  std::vector<char> on_surface(n, 0);
  const auto add = [&](Index p, std::int32_t cell) {
    std::array<std::uint32_t, 5>& a = around[p];
    const auto c = static_cast<std::uint32_t>(cell);
    if (std::find(a.begin(), a.begin() + count[p], c) == a.begin() + count[p] && count[p] < a.size()) a[count[p]++] = c;
  };
  const auto region = [&](std::int32_t cell) { return clipped.cells[static_cast<std::size_t>(cell)].region; };
  for (const VoronoiFace& f : clipped.faces) {
    const bool between = f.neighbour != kNoCell && region(f.owner) == region(f.neighbour);
    for (Index p : f.points) {
      on_surface[p] |= !between;
      if (!between) continue;
      add(p, f.owner);
      add(p, f.neighbour);
    }
  }
  DualTets out;
  for (std::size_t p = 0; p < n; ++p) {
    if (on_surface[p] || count[p] < 4) continue;
    if (count[p] > 4) {
      ++out.degenerate_points;
      continue;
    }
    std::array<std::uint32_t, 4> t{around[p][0], around[p][1], around[p][2], around[p][3]};
    const auto site = [&](int k) -> const Point& { return clipped.cells[t[k]].site; };
    if ((site(1) - site(0)).cross(site(2) - site(0)).dot(site(3) - site(0)) < 0) std::swap(t[2], t[3]);
    out.tets.push_back(t);
    out.material.push_back(clipped.cells[t[0]].region);
  }
  return out;
}

TetShape tet_shape(const Point& a, const Point& b, const Point& c, const Point& d) {
  const std::array<Point, 4> v{a, b, c, d};
  TetShape s;
  s.volume = std::abs((b - a).cross(c - a).dot(d - a)) / 6;
  // Face k is opposite vertex k; its normal points away from that vertex.
  std::array<Point, 4> normal;
  double faces_area = 0;
  for (int k = 0; k < 4; ++k) {
    const Point& p = v[(k + 1) % 4];
    const Point& q = v[(k + 2) % 4];
    const Point& r = v[(k + 3) % 4];
    Point n = (q - p).cross(r - p);
    faces_area += n.norm() / 2;
    if (n.dot(v[k] - p) > 0) n = -n;
    normal[k] = n.normalized();
  }
  s.min_dihedral = 180;
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) {
      const double outer = std::acos(std::clamp(normal[i].dot(normal[j]), -1.0, 1.0));
      const double dihedral = 180 - outer * 180 / std::numbers::pi;
      s.min_dihedral = std::min(s.min_dihedral, dihedral);
      s.max_dihedral = std::max(s.max_dihedral, dihedral);
    }
  }
  Eigen::Matrix3d m;
  m.row(0) = (b - a).transpose();
  m.row(1) = (c - a).transpose();
  m.row(2) = (d - a).transpose();
  const Eigen::Vector3d rhs((b - a).squaredNorm() / 2, (c - a).squaredNorm() / 2, (d - a).squaredNorm() / 2);
  const double circumradius = s.volume > 0 ? Point(m.fullPivLu().solve(rhs)).norm() : 0;
  const double inradius = faces_area > 0 ? 3 * s.volume / faces_area : 0;
  s.radius_ratio = circumradius > 0 ? 3 * inradius / circumradius : 0;
  s.circumradius = circumradius;
  double squares = 0;
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) squares += (v[i] - v[j]).squaredNorm();
  }
  s.q4 = squares > 0 ? 12 * std::cbrt(9 * s.volume * s.volume) / squares : 0;
  return s;
}

DualTetFigures measure_dual_tets(const VoronoiMesh& clipped) {
  const DualTets dual = dual_tets(clipped);
  DualTetFigures f;
  f.tets = dual.tets.size();
  f.degenerate_points = dual.degenerate_points;
  if (dual.tets.empty()) return f;
  f.min_min_dihedral = 180;
  f.min_radius_ratio = f.min_q4 = 1;
  for (const std::array<std::uint32_t, 4>& t : dual.tets) {
    const TetShape s = tet_shape(clipped.cells[t[0]].site, clipped.cells[t[1]].site, clipped.cells[t[2]].site,
                                 clipped.cells[t[3]].site);
    f.volume += s.volume;
    f.mean_min_dihedral += s.min_dihedral;
    f.min_min_dihedral = std::min(f.min_min_dihedral, s.min_dihedral);
    f.max_max_dihedral = std::max(f.max_max_dihedral, s.max_dihedral);
    f.mean_radius_ratio += s.radius_ratio;
    f.min_radius_ratio = std::min(f.min_radius_ratio, s.radius_ratio);
    f.mean_q4 += s.q4;
    f.min_q4 = std::min(f.min_q4, s.q4);
  }
  const auto n = static_cast<double>(dual.tets.size());
  f.mean_min_dihedral /= n;
  f.mean_radius_ratio /= n;
  f.mean_q4 /= n;
  return f;
}

}  // namespace vorocrust::clipping
