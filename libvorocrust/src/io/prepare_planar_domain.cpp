// Validating a 2D domain: points merged, crossings split, degenerate segments named (paper 2.6).
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <unordered_map>

#include "geometry/predicates.hpp"
#include "vorocrust/plane.hpp"

namespace vorocrust {

std::string describe_point(const Point2& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.9g, %.9g)", p.x(), p.y());
  return text;
}

namespace {

std::string where(const PlanarDomain& d, std::size_t segment) {
  std::string s = "segment " + std::to_string(segment + 1);
  if (segment < d.segment_lines.size() && d.segment_lines[segment] > 0) s += " (line " + std::to_string(d.segment_lines[segment]) + ")";
  return s;
}


[[noreturn]] void refuse(const PlanarDomain& d, std::size_t segment, const std::string& message) {
  const std::size_t line = segment < d.segment_lines.size() ? d.segment_lines[segment] : 0;
  throw Error(Error::Kind::InvalidGeometry, message, {.file = d.file, .line = line});
}

int orient(const Point2& a, const Point2& b, const Point2& c) {
  return geometry::orient2d(a.x(), a.y(), b.x(), b.y(), c.x(), c.y());
}

// Where along a->b the point p lies, as a fraction, for p on the line.
double along(const Point2& a, const Point2& b, const Point2& p) {
  const Point2 d = b - a;
  return (p - a).dot(d) / d.squaredNorm();
}

// Whether p lies strictly between a and b on their line (orient already 0).
bool strictly_inside(const Point2& a, const Point2& b, const Point2& p) {
  const double t = along(a, b, p);
  return t > 0 && t < 1 && p != a && p != b;
}

// Candidate pairs of segments whose bounding boxes share a grid cell.
std::vector<std::pair<std::size_t, std::size_t>> near_pairs(const std::vector<Point2>& pts,
                                                             const std::vector<std::array<Index, 2>>& segs) {
  Eigen::AlignedBox2d box;
  double total = 0;
  for (const auto& s : segs) {
    box.extend(pts[s[0]]);
    box.extend(pts[s[1]]);
    total += (pts[s[0]] - pts[s[1]]).norm();
  }
  const double cell = std::max(total / static_cast<double>(segs.size()), box.diagonal().norm() * 1e-6) * 2;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> grid;
  const auto key = [&](std::int64_t i, std::int64_t j) { return (static_cast<std::uint64_t>(i) << 32) ^ static_cast<std::uint64_t>(j & 0xffffffff); };
  const auto span = [&](std::size_t s, auto&& visit) {
    const Point2 &a = pts[segs[s][0]], &b = pts[segs[s][1]];
    const auto lo = ((a.cwiseMin(b) - box.min()) / cell).array().floor().cast<std::int64_t>();
    const auto hi = ((a.cwiseMax(b) - box.min()) / cell).array().floor().cast<std::int64_t>();
    // A segment longer than many cells is listed in each it crosses; a long one in a grid of
    // short ones costs its length in cells, not the number of segments.
    for (std::int64_t i = lo[0]; i <= hi[0]; ++i) {
      for (std::int64_t j = lo[1]; j <= hi[1]; ++j) visit(key(i, j));
    }
  };
  for (std::size_t s = 0; s < segs.size(); ++s) span(s, [&](std::uint64_t k) { grid[k].push_back(s); });
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t s = 0; s < segs.size(); ++s) {
    span(s, [&](std::uint64_t k) {
      for (std::size_t t : grid[k]) {
        if (t > s) pairs.emplace_back(s, t);
      }
    });
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

}  // namespace

PlanarDomain prepare_planar_domain(const PlanarDomain& input) {
  PlanarDomain d = input;
  if (d.segments.empty()) throw Error(Error::Kind::InvalidGeometry, "the domain has no segments", {.file = d.file});
  for (std::size_t i = 0; i < d.points.size(); ++i) {
    if (!d.points[i].allFinite()) throw Error(Error::Kind::InvalidGeometry, "point " + std::to_string(i + 1) + " is not finite", {.file = d.file});
  }
  for (const std::array<Index, 2>& s : d.segments) {
    if (s[0] >= d.points.size() || s[1] >= d.points.size()) throw Error(Error::Kind::InvalidGeometry, "a segment names a point that does not exist", {.file = d.file});
  }
  // Lengths, areas and the grid below square the coordinates: they must stay finite.
  Eigen::AlignedBox2d extent;
  double largest = 0;
  for (const Point2& p : d.points) {
    extent.extend(p);
    largest = std::max(largest, p.cwiseAbs().maxCoeff());
  }
  if (!(extent.diagonal().squaredNorm() < 1e300)) {
    char text[64];
    std::snprintf(text, sizeof text, "%g", largest);
    throw Error(Error::Kind::InvalidGeometry, std::string("the points span more than lengths in double precision can measure (coordinates up to ") +
                                                  text + "): scale the domain",
                {.file = d.file});
  }
  // Points given twice become one.
  std::map<std::pair<double, double>, Index> first_at;
  std::vector<Index> same(d.points.size());
  for (Index i = 0; i < d.points.size(); ++i) same[i] = first_at.try_emplace({d.points[i].x(), d.points[i].y()}, i).first->second;
  for (auto& s : d.segments) s = {same[s[0]], same[s[1]]};
  std::map<std::pair<Index, Index>, std::size_t> seen;
  for (std::size_t s = 0; s < d.segments.size(); ++s) {
    const auto [a, b] = d.segments[s];
    if (a == b) refuse(d, s, where(d, s) + " has zero length: both ends at " + describe_point(d.points[a]));
    const auto [it, fresh] = seen.try_emplace({std::min(a, b), std::max(a, b)}, s);
    if (!fresh) refuse(d, s, where(d, s) + " repeats " + where(d, it->second) + ", from " + describe_point(d.points[a]) + " to " + describe_point(d.points[b]));
  }
  // Crossings and points on segments, decided exactly; each segment remembers where it is split.
  std::vector<std::vector<std::pair<double, Index>>> splits(d.segments.size());
  const auto split = [&](std::size_t s, Index v) {
    splits[s].emplace_back(along(d.points[d.segments[s][0]], d.points[d.segments[s][1]], d.points[v]), v);
  };
  for (const auto& [s, t] : near_pairs(d.points, d.segments)) {
    const Index a = d.segments[s][0], b = d.segments[s][1], c = d.segments[t][0], e = d.segments[t][1];
    const Point2 &pa = d.points[a], &pb = d.points[b], &pc = d.points[c], &pe = d.points[e];
    const int o1 = orient(pa, pb, pc), o2 = orient(pa, pb, pe), o3 = orient(pc, pe, pa), o4 = orient(pc, pe, pb);
    if (o1 == 0 && o2 == 0) {
      // Collinear: they may only meet at a shared end.
      const double tc = along(pa, pb, pc), te = along(pa, pb, pe);
      const double lo = std::min(tc, te), hi = std::max(tc, te);
      if (hi > 0 && lo < 1 && !(hi <= 0 || lo >= 1)) {
        refuse(d, t, where(d, t) + " overlaps " + where(d, s) + " along a stretch from " + describe_point(d.points[lo == tc ? c : e]));
      }
      continue;
    }
    if (o1 * o2 < 0 && o3 * o4 < 0) {
      // A proper crossing: both split at one new point.
      const Point2 r = pb - pa, q = pe - pc;
      const double cross = r.x() * q.y() - r.y() * q.x();
      const double u = ((pc - pa).x() * q.y() - (pc - pa).y() * q.x()) / cross;
      const Index v = static_cast<Index>(d.points.size());
      d.points.push_back(pa + u * r);
      split(s, v);
      split(t, v);
      continue;
    }
    // One segment's end on the other's inside: the other is split there.
    if (o1 == 0 && c != a && c != b && strictly_inside(pa, pb, pc)) split(s, c);
    if (o2 == 0 && e != a && e != b && strictly_inside(pa, pb, pe)) split(s, e);
    if (o3 == 0 && a != c && a != e && strictly_inside(pc, pe, pa)) split(t, a);
    if (o4 == 0 && b != c && b != e && strictly_inside(pc, pe, pb)) split(t, b);
  }
  std::vector<std::array<Index, 2>> segments;
  std::vector<std::size_t> lines;
  for (std::size_t s = 0; s < d.segments.size(); ++s) {
    std::sort(splits[s].begin(), splits[s].end());
    Index from = d.segments[s][0];
    const std::size_t line = s < d.segment_lines.size() ? d.segment_lines[s] : 0;
    for (const auto& [t, v] : splits[s]) {
      if (v == from) continue;
      segments.push_back({from, v});
      lines.push_back(line);
      from = v;
    }
    segments.push_back({from, d.segments[s][1]});
    lines.push_back(line);
  }
  d.segments = std::move(segments);
  d.segment_lines = std::move(lines);
  // Splitting at a point already an end of another piece may give a piece twice.
  std::map<std::pair<Index, Index>, std::size_t> pieces;
  for (std::size_t s = 0; s < d.segments.size(); ++s) {
    const auto [a, b] = d.segments[s];
    if (a == b || !pieces.try_emplace({std::min(a, b), std::max(a, b)}, s).second) {
      refuse(d, s, where(d, s) + " overlaps another segment near " + describe_point(d.points[a]));
    }
  }
  return d;
}

}  // namespace vorocrust
