// Circles along the segments of a 2D domain, refined until every pair of them meets uncovered
// (paper 2.3 and 2.6: the segments as creases, the balls as circles).
#include "refinement/protect_chains.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "geometry/plane_tree.hpp"

namespace vorocrust::refinement {

using features::Chain;

bool circles_meet(const PlaneCircle& a, const PlaneCircle& b, std::array<Point2, 2>& meet) {
  const Point2 d = b.centre - a.centre;
  const double dist = d.norm();
  if (!(dist > std::abs(a.radius - b.radius)) || !(dist < a.radius + b.radius)) return false;
  const double along = (dist * dist + a.radius * a.radius - b.radius * b.radius) / (2 * dist);
  const double h = std::sqrt(std::max(0.0, a.radius * a.radius - along * along));
  const Point2 u = d / dist, left(-u.y(), u.x());
  const Point2 mid = a.centre + along * u;
  meet = {mid + h * left, mid - h * left};
  return true;
}

namespace {

constexpr double kSpacing = 1.0;      // consecutive centres at most this many of the smaller radius apart
constexpr double kShrink = 0.7;       // what a circle that covers, or is covered, keeps of its radius
constexpr double kCornerShare = 0.45;  // a corner circle reaches at most this far to the next corner
constexpr int kMaxRounds = 200;

// An upper bound on radii along one chain: min over bounds (s_k, r_k) of r_k + L |s - s_k|.
class ChainBounds {
 public:
  explicit ChainBounds(double lipschitz) : lipschitz_(lipschitz) {}
  void add(double s, double r) { bounds_.insert({s, r}); }
  double at(double s, double cap) const {
    double best = cap;
    auto right = bounds_.lower_bound({s, -1.0});
    for (auto it = right; it != bounds_.end() && lipschitz_ * (it->first - s) < best; ++it) {
      best = std::min(best, it->second + lipschitz_ * (it->first - s));
    }
    for (auto it = right; it != bounds_.begin();) {
      --it;
      if (lipschitz_ * (s - it->first) >= best) break;
      best = std::min(best, it->second + lipschitz_ * (s - it->first));
    }
    return best;
  }

 private:
  double lipschitz_;
  std::set<std::pair<double, double>> bounds_;
};

class Protection {
 public:
  Protection(const PlanarDomain& d, const features::PlaneFeatures& f, const SizingField& sizing, double lipschitz)
      : d_(d), f_(f), sizing_(sizing), lipschitz_(lipschitz) {
    Eigen::AlignedBox2d box;
    for (const auto& s : d.segments) {
      box.extend(d.points[s[0]]);
      box.extend(d.points[s[1]]);
    }
    floor_ = 1e-9 * box.diagonal().norm();
    for (std::size_t c = 0; c < f.chains.size(); ++c) bounds_.emplace_back(lipschitz);
    corner_radius_.assign(d.points.size(), 0);
    std::vector<Point2> corners;
    std::vector<Index> corner_ids;
    for (Index v = 0; v < d.points.size(); ++v) {
      if (f.corner[v]) {
        corners.push_back(d.points[v]);
        corner_ids.push_back(v);
      }
    }
    const geometry::PlaneTree tree(corners);
    for (std::size_t k = 0; k < corners.size(); ++k) {
      const Index v = corner_ids[k];
      double r = size_at(d.points[v]);
      std::uint32_t idx[2];
      double sq[2];
      if (tree.nearest(d.points[v], 2, idx, sq) == 2) r = std::min(r, kCornerShare * std::sqrt(sq[1]));
      for (const auto& [c, at_end] : f.leaving[v]) {
        const Chain& chain = f.chains[c];
        const Point2& far = d.points[at_end ? chain.points.front() : chain.points.back()];
        const double reach = far == d.points[v] ? 0.3 * chain.length() / std::numbers::pi : (far - d.points[v]).norm();
        r = std::min(r, kCornerShare * reach);
      }
      corner_radius_[v] = r;
    }
  }

  PlaneProtection run() {
    PlaneProtection out;
    for (out.rounds = 1;; ++out.rounds) {
      place(out);
      if (shrink_covering(out)) return out;
      if (out.rounds >= kMaxRounds) {
        throw Error(Error::Kind::InvalidGeometry, "the circles protecting the segments do not settle after " +
                                                      std::to_string(kMaxRounds) + " rounds",
                    {.file = d_.file});
      }
    }
  }

 private:
  double size_at(const Point2& p) const { return sizing_(Point(p.x(), p.y(), 0)); }

  // The arc length at which the chain first lies `r` from its start (or, backwards, its end).
  double reach_along(const Chain& c, double r, bool from_end) const {
    const Point2& o = d_.points[from_end ? c.points.back() : c.points.front()];
    const std::size_t n = c.points.size();
    for (std::size_t k = 1; k < n; ++k) {
      const std::size_t i = from_end ? n - k : k - 1, j = from_end ? n - 1 - k : k;
      const Point2 &a = d_.points[c.points[i]], &b = d_.points[c.points[j]];
      if ((b - o).norm() < r) continue;
      // Solve |a + t (b - a) - o| = r for the t in [0, 1] where the chain leaves the circle.
      const Point2 ab = b - a, ao = a - o;
      const double qa = ab.squaredNorm(), qb = 2 * ab.dot(ao), qc = ao.squaredNorm() - r * r;
      const double t = std::clamp((-qb + std::sqrt(std::max(0.0, qb * qb - 4 * qa * qc))) / (2 * qa), 0.0, 1.0);
      const double len = c.arc[std::max(i, j)] - c.arc[std::min(i, j)];
      return from_end ? c.arc[i] - t * len : c.arc[i] + t * len;
    }
    return from_end ? 0 : c.length();
  }

  // The angle from a chain leaving corner v to its neighbours there, the smaller side.
  double free_angle(Index v, std::uint32_t chain, bool at_end) const {
    const auto& around = f_.leaving[v];
    if (around.size() < 2) return 2 * std::numbers::pi;
    const Point2 dir = features::leaving_direction(d_, f_.chains[chain], at_end);
    double best = 2 * std::numbers::pi;
    for (const auto& [c, e] : around) {
      if (c == chain && e == at_end) continue;
      const Point2 other = features::leaving_direction(d_, f_.chains[c], e);
      best = std::min(best, std::acos(std::clamp(dir.dot(other), -1.0, 1.0)));
    }
    return best;
  }

  struct Placed {
    std::uint32_t chain;
    double s;
    bool corner;
    Index point;  // the corner's
  };

  void place(PlaneProtection& out) {
    out.circles.clear();
    out.along.assign(f_.chains.size(), {});
    out.pairs.clear();
    placed_.clear();
    corner_circle_.assign(d_.points.size(), static_cast<std::uint32_t>(-1));
    for (Index v = 0; v < d_.points.size(); ++v) {
      if (!f_.corner[v]) continue;
      corner_circle_[v] = add(out, {d_.points[v], corner_radius_[v], true}, {0, 0, true, v});
    }
    for (std::uint32_t c = 0; c < f_.chains.size(); ++c) place_chain(out, c);
  }

  std::uint32_t add(PlaneProtection& out, const PlaneCircle& circle, const Placed& where) {
    out.circles.push_back(circle);
    placed_.push_back(where);
    return static_cast<std::uint32_t>(out.circles.size() - 1);
  }

  void place_chain(PlaneProtection& out, std::uint32_t c) {
    const Chain& chain = f_.chains[c];
    const ChainBounds& bound = bounds_[c];
    const double len = chain.length();
    std::vector<std::pair<double, double>> row;  // (s, r)
    ChainBounds local = bound;
    const auto pos = [&](double s) { return features::chain_point(d_, chain, chain.loop ? std::fmod(s, len) : s); };
    const auto radius_at = [&](double s) {
      const double on = chain.loop ? std::fmod(s, len) : s;
      double r = local.at(on, size_at(pos(on)));
      if (chain.loop) r = std::min(r, local.at(on + len, r));  // bounds near the start, seen across it
      return r;
    };
    if (chain.loop) {
      for (double s : {0.0, len / 3, 2 * len / 3}) row.emplace_back(s, radius_at(s));
    } else {
      const Index u = chain.points.front(), w = chain.points.back();
      const double su = reach_along(chain, corner_radius_[u], false), sw = reach_along(chain, corner_radius_[w], true);
      const double ru = std::min(radius_at(su), first_radius(u, c, false));
      const double rw = std::min(radius_at(sw), first_radius(w, c, true));
      local.add(su, ru);
      local.add(sw, rw);
      row.emplace_back(su, ru);
      if (sw > su) row.emplace_back(sw, rw);
    }
    // Fill until consecutive circles overlap enough, and radii vary by at most L along the row.
    for (bool changed = true; changed;) {
      changed = false;
      std::vector<std::pair<double, double>> next;
      const std::size_t n = row.size(), pairs = chain.loop ? n : n - 1;
      for (std::size_t i = 0; i < n; ++i) {
        next.push_back(row[i]);
        if (i >= pairs) continue;
        const std::size_t j = (i + 1) % n;
        const double sa = row[i].first, sb = row[j].first + (j == 0 ? len : 0);
        const double gap = (pos(sa) - pos(sb)).norm(), step = kSpacing * std::min(row[i].second, row[j].second);
        if (gap > step * (1 + 1e-9) && sb - sa > 1e-12 * len) {
          // March from a to b, each step the radius where it starts; the last mark stays clear of b.
          const std::size_t first = next.size();
          for (double sm = sa + kSpacing * row[i].second; sm < sb; sm += kSpacing * next.back().second) {
            next.emplace_back(sm, radius_at(sm));
          }
          if (next.size() > first && (pos(next.back().first) - pos(sb)).norm() < 0.5 * kSpacing * row[j].second) next.pop_back();
          if (next.size() == first) next.emplace_back((sa + sb) / 2, radius_at((sa + sb) / 2));
          changed = true;
        }
      }
      if (chain.loop) {
        for (auto& [sm, r] : next) sm = sm >= len ? sm - len : sm;
        std::sort(next.begin(), next.end());
      }
      row = std::move(next);
      // Lipschitz along the row, both ways (the corner circles stay out of it).
      const auto settle = [&](std::size_t i, std::size_t j) {
        const double cap = row[j].second + lipschitz_ * (pos(row[i].first) - pos(row[j].first)).norm();
        if (row[i].second > cap) {
          row[i].second = cap;
          changed = true;
        }
      };
      for (std::size_t i = 1; i < row.size(); ++i) settle(i, i - 1);
      for (std::size_t i = row.size() - 1; i-- > 0;) settle(i, i + 1);
      if (chain.loop && row.size() > 1) {
        settle(0, row.size() - 1);
        settle(row.size() - 1, 0);
      }
    }
    std::vector<std::uint32_t>& ids = out.along[c];
    if (!chain.loop) ids.push_back(corner_circle_[chain.points.front()]);
    for (const auto& [s, r] : row) ids.push_back(add(out, {pos(s), r, false}, {c, s, false, 0}));
    if (!chain.loop) ids.push_back(corner_circle_[chain.points.back()]);
    const std::size_t n = ids.size(), pairs = chain.loop ? n : n - 1;
    for (std::size_t k = 0; k < pairs; ++k) out.pairs.push_back({ids[k], ids[(k + 1) % n], c});
  }

  // The first circle of chain c at corner v: on the corner's circle, meeting it within a third
  // of the free angle there (a circle of radius 2 R sin(phi / 2) centred on a circle of radius
  // R meets it at angle phi either side of its centre).
  double first_radius(Index v, std::uint32_t c, bool at_end) const {
    const double phi = std::min(free_angle(v, c, at_end) / 3, std::numbers::pi / 3);
    return 2 * corner_radius_[v] * std::sin(phi / 2);
  }

  void shrink(std::uint32_t circle, const PlaneProtection& out) {
    const Placed& p = placed_[circle];
    const double r = kShrink * out.circles[circle].radius;
    if (r < floor_) {
      throw Error(Error::Kind::InvalidGeometry,
                  "segments near " + describe_point(out.circles[circle].centre) +
                      " come closer than the circles protecting them can resolve (a radius below 1e-9 of the domain's "
                      "size): do they nearly touch, or meet at a tiny angle?",
                  {.file = d_.file});
    }
    if (p.corner) corner_radius_[p.point] = std::min(corner_radius_[p.point], r);
    else bounds_[p.chain].add(p.s, r);
  }

  // Shrinks the circles whose meeting points others cover; whether there were none.
  bool shrink_covering(const PlaneProtection& out) {
    std::vector<Point2> centres;
    double largest = 0;
    for (const PlaneCircle& c : out.circles) {
      centres.push_back(c.centre);
      largest = std::max(largest, c.radius);
    }
    const geometry::PlaneTree tree(centres);
    std::set<std::uint32_t> to_shrink;
    std::set<std::pair<std::uint32_t, std::uint32_t>> consecutive;
    for (const auto& [i, j, chain] : out.pairs) consecutive.insert({std::min(i, j), std::max(i, j)});
    const auto next_to = [&](std::uint32_t a, std::uint32_t b) { return consecutive.count({std::min(a, b), std::max(a, b)}) > 0; };
    std::vector<std::uint32_t> near;
    for (const auto& [i, j, chain] : out.pairs) {
      std::array<Point2, 2> meet;
      if (!circles_meet(out.circles[i], out.circles[j], meet)) {
        to_shrink.insert(i);
        to_shrink.insert(j);
        continue;
      }
      for (const Point2& p : meet) {
        tree.within(p, kCoverMargin * largest, near);
        for (std::uint32_t q : near) {
          if (q == i || q == j || !((p - centres[q]).norm() < kCoverMargin * out.circles[q].radius)) continue;
          // A corner's circle and the seeds of a chain leaving it: they lie just outside it, the
          // nearer the smaller the angle between the corner's chains; only inside it do they
          // count, and then the chain's circles shrink, which moves them off it, and the
          // corner's circle stays.
          const std::vector<std::uint32_t>& row = out.along[chain];
          // The chain's first circle stays too: smaller, it would draw the seeds nearer the
          // corner's circle. A chain too short for both corners' circles shrinks them.
          if (out.circles[q].corner && !row.empty() && (row.front() == q || row.back() == q)) {
            if (!((p - centres[q]).norm() < out.circles[q].radius)) continue;
            bool moved = false;
            for (const std::uint32_t c : {i, j}) {
              if (out.circles[c].corner || next_to(q, c)) continue;
              to_shrink.insert(c);
              moved = true;
            }
            if (!moved) {
              to_shrink.insert(q);
              for (const std::uint32_t c : {i, j}) {
                if (out.circles[c].corner) to_shrink.insert(c);
              }
            }
            continue;
          }
          to_shrink.insert(q);
          to_shrink.insert(i);
          to_shrink.insert(j);
        }
      }
    }
    for (std::uint32_t c : to_shrink) shrink(c, out);
    return to_shrink.empty();
  }

  const PlanarDomain& d_;
  const features::PlaneFeatures& f_;
  const SizingField& sizing_;
  double lipschitz_;
  double floor_ = 0;
  std::vector<ChainBounds> bounds_;
  std::vector<double> corner_radius_;
  std::vector<Placed> placed_;
  std::vector<std::uint32_t> corner_circle_;
};

}  // namespace

PlaneProtection protect_chains(const PlanarDomain& domain, const features::PlaneFeatures& features,
                               const SizingField& sizing, double lipschitz) {
  return Protection(domain, features, sizing, lipschitz).run();
}

}  // namespace vorocrust::refinement
