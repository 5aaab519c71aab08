#include "clipping/polygon_holes.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <optional>
#include <utility>

#include "geometry/predicates.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust::clipping {
namespace {

using Point2 = Eigen::Vector2d;

// The plane's points in two coordinates, counter-clockwise about `normal` staying so.
class Projection {
 public:
  explicit Projection(const Point& normal) {
    Eigen::Index k = 0;
    normal.cwiseAbs().maxCoeff(&k);
    u_ = static_cast<int>((k + 1) % 3);
    v_ = static_cast<int>((k + 2) % 3);
    if (normal[k] < 0) std::swap(u_, v_);
  }
  Point2 operator()(const Point& p) const { return {p[u_], p[v_]}; }

 private:
  int u_ = 0, v_ = 1;
};

int orient(const Point2& a, const Point2& b, const Point2& c) {
  return geometry::orient2d(a.x(), a.y(), b.x(), b.y(), c.x(), c.y());
}

bool inside(const Point2& p, const std::vector<Point2>& polygon) {
  bool in = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      in = !in;
    }
  }
  return in;
}

struct Region {
  const std::function<const Point&(Index)>& at;
  Projection projection;
  Point2 operator()(Index i) const { return projection(at(i)); }
  std::vector<Point2> polygon(const Loop& loop) const {
    std::vector<Point2> out;
    for (Index i : loop) out.push_back((*this)(i));
    return out;
  }
};

// Whether the segment from a to b runs inside the region: it crosses no loop edge and no
// diagonal already drawn, passes through no other point, and its middle is inside.
bool free_diagonal(const Region& region, Index a, Index b, const Loop& outer, const std::vector<Loop>& holes,
                   const std::optional<std::pair<Index, Index>>& drawn) {
  const Point2 pa = region(a), pb = region(b);
  const auto crosses = [&](Index c, Index d) {
    if (c == a || c == b || d == a || d == b) return false;
    const Point2 pc = region(c), pd = region(d);
    return orient(pa, pb, pc) * orient(pa, pb, pd) < 0 && orient(pc, pd, pa) * orient(pc, pd, pb) < 0;
  };
  const auto on = [&](Index c) {
    if (c == a || c == b) return false;
    const Point2 pc = region(c);
    return orient(pa, pb, pc) == 0 && (pc - pa).dot(pb - pa) > 0 && (pc - pb).dot(pa - pb) > 0;
  };
  const auto blocked_by = [&](const Loop& loop) {
    for (std::size_t k = 0; k < loop.size(); ++k) {
      if (crosses(loop[k], loop[(k + 1) % loop.size()]) || on(loop[k])) return true;
    }
    return false;
  };
  if (blocked_by(outer) || std::any_of(holes.begin(), holes.end(), blocked_by)) return false;
  if (drawn && (drawn->first == a || drawn->second == b || crosses(drawn->first, drawn->second))) return false;
  const Point2 middle = (pa + pb) / 2;
  if (!inside(middle, region.polygon(outer))) return false;
  return std::none_of(holes.begin(), holes.end(), [&](const Loop& h) { return inside(middle, region.polygon(h)); });
}

// The shortest free diagonal from hole `h` to the outer loop, as positions in each.
std::optional<std::pair<std::size_t, std::size_t>> diagonal(const Region& region, const Loop& outer,
                                                            const std::vector<Loop>& holes, std::size_t h,
                                                            const std::optional<std::pair<Index, Index>>& drawn) {
  std::vector<std::pair<double, std::pair<std::size_t, std::size_t>>> candidates;
  for (std::size_t i = 0; i < holes[h].size(); ++i) {
    for (std::size_t j = 0; j < outer.size(); ++j) {
      candidates.push_back({(region(holes[h][i]) - region(outer[j])).squaredNorm(), {i, j}});
    }
  }
  std::sort(candidates.begin(), candidates.end());
  for (const auto& [length, c] : candidates) {
    if (free_diagonal(region, holes[h][c.first], outer[c.second], outer, holes, drawn)) return c;
  }
  return std::nullopt;
}

// loop[from], loop[from + 1], ..., loop[to], cyclically, appended to `out`.
void append_run(const Loop& loop, std::size_t from, std::size_t to, Loop& out) {
  for (std::size_t k = from;; k = (k + 1) % loop.size()) {
    out.push_back(loop[k]);
    if (k == to) break;
  }
}

void fill(const Region& region, const Loop& outer, std::vector<Loop> holes, std::vector<Loop>& out) {
  if (holes.empty()) {
    out.push_back(outer);
    return;
  }
  const auto first = diagonal(region, outer, holes, 0, std::nullopt);
  const auto second =
      first ? diagonal(region, outer, holes, 0, std::pair(holes[0][first->first], outer[first->second])) : std::nullopt;
  if (!second) throw Error(Error::Kind::Internal, "a hole of a clipped face cannot be joined to its outline");
  const Loop& hole = holes[0];
  const auto [i1, j1] = *first;
  const auto [i2, j2] = *second;
  Loop a, b;
  append_run(outer, j1, j2, a);
  append_run(hole, i2, i1, a);
  append_run(outer, j2, j1, b);
  append_run(hole, i1, i2, b);
  std::vector<Loop> in_a, in_b;
  const std::vector<Point2> polygon_a = region.polygon(a);
  for (std::size_t k = 1; k < holes.size(); ++k) {
    (inside(region(holes[k].front()), polygon_a) ? in_a : in_b).push_back(std::move(holes[k]));
  }
  fill(region, a, std::move(in_a), out);
  fill(region, b, std::move(in_b), out);
}

}  // namespace

std::vector<Loop> simple_polygons(std::vector<Loop> loops, const std::function<const Point&(Index)>& at,
                                  const Point& normal) {
  const Region region{at, Projection(normal)};
  const auto twice_area = [&](const Loop& loop) {
    double sum = 0;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Point2 a = region(loop[k]), b = region(loop[(k + 1) % loop.size()]);
      sum += a.x() * b.y() - a.y() * b.x();
    }
    return sum;
  };
  std::vector<Loop> outers, holes;
  for (Loop& loop : loops) (twice_area(loop) > 0 ? outers : holes).push_back(std::move(loop));
  std::vector<std::vector<Loop>> holes_of(outers.size());
  for (Loop& hole : holes) {
    const Point2 p = region(hole.front());
    std::size_t k = 0;
    while (k < outers.size() && !inside(p, region.polygon(outers[k]))) ++k;
    if (k == outers.size()) throw Error(Error::Kind::Internal, "a hole of a clipped face lies in no outline");
    holes_of[k].push_back(std::move(hole));
  }
  std::vector<Loop> out;
  for (std::size_t k = 0; k < outers.size(); ++k) fill(region, outers[k], std::move(holes_of[k]), out);
  return out;
}

}  // namespace vorocrust::clipping
