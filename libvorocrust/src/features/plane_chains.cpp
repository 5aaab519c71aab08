// Corners and chains of a 2D domain (paper 2.2, 2.6: the boundary as creases).
#include "features/plane_chains.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vorocrust::features {

namespace {

double angle_of(const Point2& d) { return std::atan2(d.y(), d.x()); }

}  // namespace

Point2 chain_point(const PlanarDomain& d, const Chain& c, double s) {
  s = std::clamp(s, 0.0, c.length());
  const std::size_t k = std::min<std::size_t>(
      static_cast<std::size_t>(std::upper_bound(c.arc.begin(), c.arc.end(), s) - c.arc.begin()), c.arc.size() - 1);
  const std::size_t i = k == 0 ? 0 : k - 1;
  const double span = c.arc[i + 1] - c.arc[i];
  const double t = span > 0 ? (s - c.arc[i]) / span : 0;
  return (1 - t) * d.points[c.points[i]] + t * d.points[c.points[i + 1]];
}

Point2 chain_direction(const PlanarDomain& d, const Chain& c, double s) {
  s = std::clamp(s, 0.0, c.length());
  std::size_t i = static_cast<std::size_t>(std::upper_bound(c.arc.begin(), c.arc.end(), s) - c.arc.begin());
  i = std::clamp<std::size_t>(i, 1, c.arc.size() - 1) - 1;
  return (d.points[c.points[i + 1]] - d.points[c.points[i]]).normalized();
}

Point2 leaving_direction(const PlanarDomain& d, const Chain& c, bool at_end) {
  const std::size_t n = c.points.size();
  return at_end ? (d.points[c.points[n - 2]] - d.points[c.points[n - 1]]).normalized()
                : (d.points[c.points[1]] - d.points[c.points[0]]).normalized();
}

PlaneFeatures find_plane_features(const PlanarDomain& d, double sharp_angle_degrees) {
  const std::size_t n = d.points.size();
  std::vector<std::vector<std::uint32_t>> incident(n);
  for (std::uint32_t s = 0; s < d.segments.size(); ++s) {
    incident[d.segments[s][0]].push_back(s);
    incident[d.segments[s][1]].push_back(s);
  }
  const auto other = [&](std::uint32_t s, Index v) { return d.segments[s][0] == v ? d.segments[s][1] : d.segments[s][0]; };
  PlaneFeatures f;
  f.corner.assign(n, false);
  const double sharp = sharp_angle_degrees * std::numbers::pi / 180;
  for (Index v = 0; v < n; ++v) {
    if (incident[v].empty()) continue;
    if (incident[v].size() != 2) {
      f.corner[v] = true;
      continue;
    }
    const Point2 in = d.points[v] - d.points[other(incident[v][0], v)];
    const Point2 out = d.points[other(incident[v][1], v)] - d.points[v];
    const double turn = std::acos(std::clamp(in.normalized().dot(out.normalized()), -1.0, 1.0));
    f.corner[v] = turn > sharp;
  }
  std::vector<bool> used(d.segments.size(), false);
  const auto walk = [&](Index start, std::uint32_t first) {
    Chain c;
    c.points = {start};
    c.arc = {0};
    Index v = start;
    std::uint32_t s = first;
    while (true) {
      used[s] = true;
      const Index w = other(s, v);
      c.arc.push_back(c.arc.back() + (d.points[w] - d.points[v]).norm());
      c.points.push_back(w);
      v = w;
      if (f.corner[v] || v == start) break;
      const std::uint32_t next = incident[v][0] == s ? incident[v][1] : incident[v][0];
      if (used[next]) break;
      s = next;
    }
    return c;
  };
  for (Index v = 0; v < n; ++v) {
    if (!f.corner[v]) continue;
    for (std::uint32_t s : incident[v]) {
      if (!used[s]) f.chains.push_back(walk(v, s));
    }
  }
  for (Index v = 0; v < n; ++v) {
    for (std::uint32_t s : incident[v]) {
      if (used[s]) continue;
      Chain c = walk(v, s);
      c.loop = true;
      f.chains.push_back(std::move(c));
    }
  }
  f.leaving.resize(n);
  for (std::uint32_t c = 0; c < f.chains.size(); ++c) {
    const Chain& chain = f.chains[c];
    if (chain.loop) continue;
    f.leaving[chain.points.front()].emplace_back(c, false);
    f.leaving[chain.points.back()].emplace_back(c, true);
  }
  for (Index v = 0; v < n; ++v) {
    std::sort(f.leaving[v].begin(), f.leaving[v].end(), [&](const auto& a, const auto& b) {
      return angle_of(leaving_direction(d, f.chains[a.first], a.second)) <
             angle_of(leaving_direction(d, f.chains[b.first], b.second));
    });
  }
  return f;
}

}  // namespace vorocrust::features
