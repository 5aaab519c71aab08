// Recursive maximal Poisson-disk sampling of balls (paper section 2.3).
#include "refinement/refine_balls.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <string_view>

#include "core/surface_measures.hpp"
#include "geometry/box_tree.hpp"
#include "refinement/ball_index.hpp"
#include "refinement/subface.hpp"
#include "refinement/union_cover.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust {

namespace {

constexpr double kAlpha = 0.13397459621556135;  // 1 - sqrt(3)/2 (paper 2.3, Deep Coverage)
constexpr double kDeep = 1 - kAlpha;
constexpr double kSeparation = 0.49;              // r_p <= 0.49 |p - q*|
constexpr std::size_t kMissLimit = 100;           // consecutive misses before subdividing
constexpr double kDensityRejection = 0.1;         // density regulation
constexpr int kMaxDepth = 40;                     // subdivision levels: 2^-40 of an element

using Clock = std::chrono::steady_clock;

// How far a ball counts as covering for the phase sampling `phase`. Balls of the phase itself
// cover deeply (C4). Balls of a lower type keep the phase out of all they contain (paper 2.3),
// except that a corner ball keeps a crease out only of what it covers deeply: every crease point
// then lies deep inside some protecting ball, so their union holds a tube of positive width
// around each crease and patch balls, which must stay clear of creases, never shrink without end.
double covering_radius(StratumType phase, StratumType ball_type, double radius, double deep) {
  if (ball_type == phase) return deep * radius;
  if (phase == StratumType::Crease && ball_type == StratumType::Corner) return deep * radius;
  return radius;
}
// A ball that must shrink to `radius`.
struct Shrink {
  std::uint32_t ball;
  double radius;
};

// A ball that reaches a piece of the pool, as the tests of the piece's children need it.
struct Candidate {
  Point centre;
  double radius;
  double limit;              // within this distance it covers for the phase (0: it cannot)
  std::uint32_t ball;
  bool cosmooth_everywhere;  // every point of the piece is co-smooth with it
};

// Whether some point of the piece lies strictly within `distance` of `centre`: a corner often
// shows it before the nearest point is worked out.
bool reaches_within(const Subface& s, const Point& centre, double distance) {
  for (int k = 0; k < s.corner_count(); ++k) {
    if ((s.corner(k) - centre).squaredNorm() < distance * distance) return true;
  }
  return (s.closest_point(centre) - centre).squaredNorm() < distance * distance;
}

// The active pool (paper 2.3): pieces, each with the balls that reached it when it was made (a
// child's are among its parent's), except those numbered `known` or later, which came since.
struct Pool {
  std::vector<Subface> pieces;
  std::vector<std::uint32_t> first{0};  // piece i's balls are reaching[first[i], first[i + 1])
  std::vector<std::uint32_t> reaching;
  std::uint32_t known = 0;
};

// Where a shrunk ball gave up cover: the shell between the radius within which it still covers
// for any phase and the radius it had. Cover lost anywhere lies in such a shell, since a ball
// covers within its radius (or a fixed share of it) wherever it covers at all.
struct LostShell {
  Point centre;
  double kept;      // kDeep times the new radius
  double given_up;  // the old radius

  geometry::Box box() const {
    geometry::Box b;
    b.include(Point(centre.array() - given_up));
    b.include(Point(centre.array() + given_up));
    return b;
  }
  // Whether the convex hull of `corners` meets the shell; `closest` gives its point nearest to a point.
  template <class Closest>
  bool meets(const Point* corners, int count, Closest&& closest) const {
    bool inside = true;
    for (int k = 0; k < count && inside; ++k) inside = (corners[k] - centre).squaredNorm() < kept * kept;
    return !inside && (closest(centre) - centre).squaredNorm() < given_up * given_up;
  }
};

// The shells given up, in a tree of their boxes: a piece of an element that lost cover needs
// sampling only where it meets one of them.
class LostRegions {
 public:
  explicit LostRegions(std::vector<LostShell> shells) : shells_(std::move(shells)), tree_(boxes(shells_), numbered(shells_.size())) {}
  bool meets(const Subface& piece) const {
    if (!piece.focused) return true;
    geometry::Box box;
    std::array<Point, 3> corners;
    for (int k = 0; k < piece.corner_count(); ++k) box.include(corners[k] = piece.corner(k));
    bool hit = false;
    tree_.for_each_where([&](const geometry::Box& b) { return !hit && b.overlaps(box); }, [&](std::uint32_t i) {
      const LostShell& shell = shells_[i];
      if (box.squared_distance(shell.centre) >= shell.given_up * shell.given_up) return;
      hit = shell.meets(corners.data(), piece.corner_count(), [&](const Point& q) { return piece.closest_point(q); });
    });
    return hit;
  }

 private:
  static std::vector<geometry::Box> boxes(const std::vector<LostShell>& shells) {
    std::vector<geometry::Box> out;
    out.reserve(shells.size());
    for (const LostShell& s : shells) out.push_back(s.box());
    return out;
  }
  static std::vector<std::uint32_t> numbered(std::size_t n) {
    std::vector<std::uint32_t> items(n);
    for (std::uint32_t i = 0; i < n; ++i) items[i] = i;
    return items;
  }
  std::vector<LostShell> shells_;
  geometry::BoxTree tree_;
};

double diagonal(const SurfaceMesh& mesh) {
  Eigen::AlignedBox3d box;
  for (const Point& p : mesh.vertices) box.extend(p);
  return box.diagonal().norm();
}

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace

class BallRefinement::Impl {
 public:
  Impl(const SurfaceMesh& mesh, const Strata& strata, const SizingField& sizing, const RefinementOptions& options,
          const ProgressCallback& progress, RefinementStats& stats)
      : mesh_(mesh),
        strata_(strata),
        sizing_(sizing),
        options_(options),
        progress_(progress),
        stats_(stats),
        cosmooth_(strata, options.sharp_angle, 1e-12 * diagonal(mesh)),
        boundary_(mesh, strata, options.samples, options.seed),
        rng_(options.seed),
        dirty_edge_(strata.topology.num_edges(), kClean),
        dirty_face_(mesh.num_faces(), kUnsampled) {
    for (std::size_t e = 0; e < dirty_edge_.size(); ++e) {
      if (strata.edge_crease[e] != Strata::kNone) dirty_edge_[e] = kUnsampled;
    }
    min_radius_ = 1e-9 * diagonal(mesh);
    build_element_trees();
    stats_.boundary_samples = boundary_.size();
  }

  void run();
  const BallIndex& balls() const { return balls_; }
  void shrink_for_slivers(std::uint32_t ball, double radius) { shrink(ball, radius, Reason::Sliver); }
  void shrink_for_skinny_triangle(std::uint32_t ball, double radius) { shrink(ball, radius, Reason::SkinnyTriangle); }
  double deep_coverage() const { return deep_; }
  void relax_deep_coverage() { deep_ = 1 - kAlpha / 2; }

 private:
  // --- phases ---------------------------------------------------------------------------------
  void protect_corners();
  void sample(StratumType type);  // MPS over the dirty elements of one stratum type
  void enforce_lipschitz(StratumType type);
  bool sweep();  // true when it shrank something

  // --- MPS pieces -----------------------------------------------------------------------------
  bool try_dart(StratumType type, const SurfaceSite& site);
  bool covered(StratumType type, const SurfaceSite& site);
  double initial_radius(const SurfaceSite& site);
  void shrink_neighbours_for_lipschitz(std::uint32_t ball);
  // Balls of every type that reach piece i of the pool; `fresh` holds the balls that came since
  // the pool was made (none for a pool just made, whose pieces ask the index of all balls).
  void reaching(const Pool& pool, std::size_t i, const geometry::BallTree& fresh, std::vector<std::uint32_t>& out) const;
  void classify(StratumType type, const Subface& s, const std::vector<std::uint32_t>& reaching,
                std::vector<Candidate>& out) const;
  bool covers(const Subface& s, const std::vector<Candidate>& candidates, std::vector<CoverBall>& cover) const;
  void find_violations(const Subface& s, const std::vector<Candidate>& candidates, std::vector<Shrink>& out) const;
  SurfaceSite site_on(const Subface& s, const Point& p) const;
  Pool initial_pool(StratumType type);
  void throw_darts(StratumType type, const std::vector<Subface>& pool, std::string_view phase);
  Pool subdivide(StratumType type, const Pool& pool, bool last_level, const LostRegions& lost);
  // sizes[d]: the pool after d subdivisions of this pass.
  void check_pool_size(const std::vector<Subface>& pool, const std::vector<std::size_t>& sizes) const;
  void defer_lost_lower_cover(Pool& pool);

  // --- shrinking ------------------------------------------------------------------------------
  enum class Reason { C1, C3, Sliver, SkinnyTriangle };  // C1 also stands for C2
  void shrink(std::uint32_t ball, double radius, Reason why);
  void mark_dirty(const LostShell& shell, StratumType type);
  void build_element_trees();
  void report(std::string_view phase, double fraction);
  bool has_dirty(StratumType type) const {
    const auto& flags = type == StratumType::Crease ? dirty_edge_ : dirty_face_;
    return std::any_of(flags.begin(), flags.end(), [](char f) { return f != kClean; });
  }

  const SurfaceMesh& mesh_;
  const Strata& strata_;
  const SizingField& sizing_;
  const RefinementOptions options_;  // a copy: callers pass temporaries
  const ProgressCallback& progress_;
  RefinementStats& stats_;
  CoSmoothness cosmooth_;
  BoundarySamples boundary_;
  BallIndex balls_;
  std::mt19937_64 rng_;
  std::uniform_real_distribution<double> unit_{0.0, 1.0};
  // Per element: kClean, kLostCover (a shrunk ball gave up part of it) or kUnsampled.
  static constexpr char kClean = 0, kLostCover = 1, kUnsampled = 2;
  std::vector<char> dirty_edge_, dirty_face_;
  // The shells the balls that shrank gave up, for the crease and the patch phase apart: each
  // phase consumes its own, so a crease pass cannot take the patches' regions.
  std::vector<LostShell> lost_edges_, lost_faces_;
  // The type being sampled, and where balls of a lower type shrank during its pass.
  int sampling_type_ = 3;
  std::vector<geometry::Box> lost_lower_;
  std::vector<bool> corner_placed_;
  std::vector<std::uint32_t> unsettled_[3];  // per stratum type: balls that may break C3 (enforce_lipschitz)
  int lowest_shrunk_ = 3;
  int restart_phase_ = 0;  // where the next run() starts: the lowest type shrunk since the last run()
  double deep_ = kDeep;    // C4: coverage must be this deep (1 - alpha)
  int passes_[3] = {0, 0, 0};  // per stratum type: sampling passes so far, named in progress
  std::uint32_t swept_ = 0;    // balls numbered below this have been through a sweep
  double min_radius_ = 0;
  std::unique_ptr<geometry::BoxTree> edge_tree_, face_tree_;
  std::vector<std::uint32_t> scratch_;
};

void BallRefinement::Impl::report(std::string_view phase, double fraction) {
  if (progress_ && !progress_({phase, fraction})) throw Error(Error::Kind::Cancelled, "cancelled during refinement");
}

void BallRefinement::Impl::build_element_trees() {
  std::vector<geometry::Box> edge_boxes(strata_.topology.num_edges());
  std::vector<std::uint32_t> edges;
  for (std::uint32_t e = 0; e < edge_boxes.size(); ++e) {
    if (strata_.edge_crease[e] == Strata::kNone) continue;
    for (Index v : strata_.topology.edges[e]) edge_boxes[e].include(mesh_.vertices[v]);
    edges.push_back(e);
  }
  edge_tree_ = std::make_unique<geometry::BoxTree>(std::move(edge_boxes), std::move(edges));
  face_tree_ = std::make_unique<geometry::BoxTree>(geometry::face_tree(mesh_));
}

// Elements of the strata a ball of `type` could cover — its own type and the higher ones — that
// meet the shell it gave up must be sampled again.
void BallRefinement::Impl::mark_dirty(const LostShell& shell, StratumType type) {
  const geometry::Box query = shell.box();
  if (type <= StratumType::Crease) {
    edge_tree_->for_each_overlap(query, [&](std::uint32_t e) {
      const auto [a, b] = strata_.topology.edges[e];
      const Point ends[2] = {mesh_.vertices[a], mesh_.vertices[b]};
      const auto closest = [&](const Point& q) { return geometry::closest_on_segment(q, ends[0], ends[1]); };
      if (shell.meets(ends, 2, closest)) dirty_edge_[e] = std::max(dirty_edge_[e], kLostCover);
    });
  }
  face_tree_->for_each_overlap(query, [&](std::uint32_t f) {
    const Triangle& t = mesh_.triangles[f];
    const Point corners[3] = {mesh_.vertices[t[0]], mesh_.vertices[t[1]], mesh_.vertices[t[2]]};
    const auto closest = [&](const Point& q) { return geometry::closest_on_triangle(q, corners[0], corners[1], corners[2]); };
    if (shell.meets(corners, 3, closest)) dirty_face_[f] = std::max(dirty_face_[f], kLostCover);
  });
  if (type <= StratumType::Crease) lost_edges_.push_back(shell);
  lost_faces_.push_back(shell);
}

void BallRefinement::Impl::shrink(std::uint32_t ball, double radius, Reason why) {
  const RefinedBall& b = balls_[ball];
  if (!(radius < b.radius)) return;
  const double old_radius = b.radius;
  balls_.shrink(ball, radius);
  ++(why == Reason::C1       ? stats_.c1_shrinks
     : why == Reason::C3     ? stats_.c3_shrinks
     : why == Reason::Sliver ? stats_.sliver_shrinks
                             : stats_.skinny_triangle_shrinks);
  if (why != Reason::C3) unsettled_[static_cast<int>(b.site.type)].push_back(ball);
  lowest_shrunk_ = std::min(lowest_shrunk_, static_cast<int>(b.site.type));
  restart_phase_ = std::min(restart_phase_, static_cast<int>(b.site.type));
  if (static_cast<int>(b.site.type) < sampling_type_) {
    geometry::Box& box = lost_lower_.emplace_back();
    box.include(Point(b.site.position.array() - old_radius));
    box.include(Point(b.site.position.array() + old_radius));
  }
  mark_dirty({b.site.position, kDeep * radius, old_radius}, b.site.type);
}

// The paper bounds r_p by the ball nearest to p alone (r_q + L |p - q|); the bound over every ball
// of the type leaves no C3 violation by the new ball.
double BallRefinement::Impl::initial_radius(const SurfaceSite& site) {
  const double r = std::min(sizing_(site.position), balls_.lipschitz_bound(site.type, site.position, options_.lipschitz));
  // q* matters only where 0.49 |p - q*| would undercut the other bounds.
  return std::min(r, kSeparation * boundary_.distance_to_non_cosmooth(site, cosmooth_, r / kSeparation));
}

// C3 the other way round: a small new ball (near a feature, where q* is close) makes larger
// neighbours violate r_q <= r_p + L |p - q|. Shrinking them now, rather than when the phase ends,
// spares the pieces they would have let go and a whole pass to cover what they give up. One
// pass suffices: r_p + L |p - q| is L-Lipschitz in q.
void BallRefinement::Impl::shrink_neighbours_for_lipschitz(std::uint32_t ball) {
  const RefinedBall& p = balls_[ball];
  const double L = options_.lipschitz;
  scratch_.clear();
  balls_.lipschitz_violators(p.site.type, p.site.position, p.radius, L, scratch_);
  for (std::uint32_t q : scratch_) {
    shrink(q, p.radius + L * (balls_[q].site.position - p.site.position).norm(), Reason::C3);
  }
}

// Paper 2.3: a dart lands where no ball covers it (covering_radius). A
// ball that holds the dart without being co-smooth with it violates C1: it shrinks (paper 2.3,
// "Detecting Violations") instead of keeping the dart out, or that region would never fill.
bool BallRefinement::Impl::covered(StratumType type, const SurfaceSite& site) {
  bool result = false;
  for (int t = 0; t <= static_cast<int>(type) && !result; ++t) {
    scratch_.clear();
    balls_.reaching(static_cast<StratumType>(t), site.position, 0.0, scratch_);
    for (std::uint32_t b : scratch_) {  // shrink() leaves scratch_ alone
      const RefinedBall& ball = balls_[b];
      const double d = (ball.site.position - site.position).norm();
      if (!cosmooth_(ball.site, site)) {
        shrink(b, kSeparation * d, Reason::C1);
        continue;
      }
      if (d <= covering_radius(type, ball.site.type, ball.radius, deep_)) result = true;
    }
  }
  return result;
}

bool BallRefinement::Impl::try_dart(StratumType type, const SurfaceSite& site) {
  ++stats_.darts;
  if (covered(type, site)) return false;
  double r = initial_radius(site);
  // Density regulation: a ball that would hold another centre deeply is rejected now and then,
  // otherwise shrunk to meet C4.
  scratch_.clear();
  for (int t = 0; t < 3; ++t) balls_.centres_within(static_cast<StratumType>(t), site.position, kDeep * r, scratch_);
  if (!scratch_.empty()) {
    if (unit_(rng_) < kDensityRejection) {
      ++stats_.rejected_for_density;
      return false;
    }
    for (std::uint32_t b : scratch_) r = std::min(r, (balls_[b].site.position - site.position).norm() / kDeep);
  }
  if (!(r > min_radius_)) return false;
  shrink_neighbours_for_lipschitz(balls_.add(site, r));
  return true;
}

SurfaceSite BallRefinement::Impl::site_on(const Subface& s, const Point& p) const {
  return s.is_segment() ? crease_site(strata_, s.element, p) : patch_site(strata_, s.element, p);
}

void BallRefinement::Impl::reaching(const Pool& pool, std::size_t i, const geometry::BallTree& fresh,
                                    std::vector<std::uint32_t>& out) const {
  out.clear();
  const Subface& s = pool.pieces[i];
  const Point centroid = s.centroid();
  const double reach = s.circumradius(centroid);
  if (pool.known == 0) {  // a pool just made: no ball inherited, none in `fresh`
    for (int t = 0; t < 3; ++t) balls_.reaching(static_cast<StratumType>(t), centroid, reach, out);
    return;
  }
  for (std::uint32_t k = pool.first[i]; k < pool.first[i + 1]; ++k) {
    const RefinedBall& ball = balls_[pool.reaching[k]];
    const double limit = ball.radius + reach;
    if ((ball.site.position - centroid).squaredNorm() < limit * limit) out.push_back(pool.reaching[k]);
  }
  fresh.search(
      centroid, [&](double d2, double max_radius, std::uint32_t) { return d2 < (max_radius + reach) * (max_radius + reach); },
      [&](const geometry::BallTree::Sphere& s) {
        if ((s.centre - centroid).squaredNorm() < (s.radius + reach) * (s.radius + reach)) out.push_back(s.ball);
      });
}

// What each ball reaching a piece can do for the piece's children, worked out once for all four:
// the radius within which it covers for the phase, and whether every point of the piece is
// co-smooth with it (on a patch face, the points beyond the face's non-co-smooth reach are).
void BallRefinement::Impl::classify(StratumType type, const Subface& s, const std::vector<std::uint32_t>& reaching,
                                    std::vector<Candidate>& out) const {
  const Point centroid = s.centroid();
  const double reach = s.circumradius(centroid);
  out.clear();
  for (std::uint32_t b : reaching) {
    const RefinedBall& ball = balls_[b];
    // Balls that reach the sphere about the piece but not the piece itself are dropped here
    // rather than tested against each child: a thin piece fills little of its sphere (on
    // netgen_hinge and cgal_joint a whole face met hundreds of balls that way).
    if ((s.closest_point(ball.site.position) - ball.site.position).squaredNorm() > ball.radius * ball.radius) continue;
    const double gap = (ball.site.position - centroid).norm() - reach;  // to the piece, at least
    const bool everywhere = !s.is_segment() && gap >= cosmooth_.non_cosmooth_reach(ball.site, s.element, s.corner(0));
    const double limit = ball.site.type > type ? 0 : covering_radius(type, ball.site.type, ball.radius, deep_);
    out.push_back({ball.site.position, ball.radius, limit, b, everywhere});
  }
}

// A subface leaves the pool once it is covered: by balls of a lower type (whose inside is kept
// from higher phases) or deeply by balls of its own type, every ball co-smooth with it. One ball
// is tried first; then their union, which spares splitting the fringe where balls meet down to
// pieces that fit in one. Balls are first judged by the sphere around the piece.
bool BallRefinement::Impl::covers(const Subface& s, const std::vector<Candidate>& candidates,
                                  std::vector<CoverBall>& cover) const {
  const Point centroid = s.centroid();
  const double reach = s.circumradius(centroid);
  const SurfaceSite site = site_on(s, centroid);
  cover.clear();
  for (const Candidate& c : candidates) {
    const double d2 = (c.centre - centroid).squaredNorm();
    if (d2 >= (c.limit + reach) * (c.limit + reach)) continue;  // the piece lies beyond it
    const bool holds_all = c.limit > reach && d2 < (c.limit - reach) * (c.limit - reach);
    if (!holds_all && !reaches_within(s, c.centre, c.limit)) continue;
    if (!c.cosmooth_everywhere && !cosmooth_(balls_[c.ball].site, site)) continue;
    if (holds_all) return true;
    cover.push_back({c.centre, c.limit});
  }
  for (const CoverBall& c : cover) {
    bool all = true;
    for (int k = 0; k < s.corner_count() && all; ++k) all = (s.corner(k) - c.centre).norm() <= c.radius;
    if (all) return true;
  }
  if (s.is_segment()) return segment_covered(s.corner(0), s.corner(1), cover);
  return triangle_covered(s.corner(0), s.corner(1), s.corner(2), cover);
}

// Paper 2.3 "Detecting Violations": every ball reaching the subface must be co-smooth with it,
// checked at the point of the subface nearest to the centre and at the corners it contains.
void BallRefinement::Impl::find_violations(const Subface& s, const std::vector<Candidate>& candidates,
                                           std::vector<Shrink>& out) const {
  const Point centroid = s.centroid();
  const double reach = s.circumradius(centroid);
  for (const Candidate& c : candidates) {
    if (c.cosmooth_everywhere) continue;
    const std::uint32_t b = c.ball;
    const RefinedBall& ball = balls_[b];
    const double gap = (ball.site.position - centroid).norm() - reach;  // to the piece, at least
    if (gap >= ball.radius) continue;
    // On a patch face, points beyond the face's non-co-smooth reach all are co-smooth.
    if (!s.is_segment() && gap >= cosmooth_.non_cosmooth_reach(ball.site, s.element, s.corner(0))) continue;
    const Point q = s.closest_point(ball.site.position);
    const double d = (q - ball.site.position).norm();
    if (!(d < ball.radius)) continue;
    bool violates = !cosmooth_(ball.site, site_on(s, q));
    for (int k = 0; k < s.corner_count() && !violates; ++k) {
      if ((s.corner(k) - ball.site.position).norm() < ball.radius) violates = !cosmooth_(ball.site, site_on(s, s.corner(k)));
    }
    if (violates) out.push_back({b, kSeparation * d});
  }
}

void BallRefinement::Impl::protect_corners() {
  corner_placed_.resize(strata_.corners.size(), false);
  for (Index c = 0; c < strata_.corners.size(); ++c) {
    if (corner_placed_[c]) continue;
    const SurfaceSite site = corner_site(strata_, mesh_, c);
    const double bound = sizing_(site.position);
    double r = std::min(bound, kSeparation * boundary_.distance_to_non_cosmooth(site, cosmooth_, bound / kSeparation));
    if (!std::isfinite(r)) r = std::numeric_limits<double>::max();  // a lone corner with nothing near
    unsettled_[static_cast<int>(StratumType::Corner)].push_back(balls_.add(site, r));
    corner_placed_[c] = true;
  }
}

Pool BallRefinement::Impl::initial_pool(StratumType type) {
  std::vector<Subface> pool;
  if (type == StratumType::Crease) {
    for (Index e = 0; e < dirty_edge_.size(); ++e) {
      if (dirty_edge_[e] == kClean) continue;
      const auto [a, b] = strata_.topology.edges[e];
      pool.push_back(Subface::segment(mesh_.vertices[a], mesh_.vertices[b], e));
      pool.back().focused = dirty_edge_[e] == kLostCover;
      dirty_edge_[e] = kClean;
    }
  } else {
    for (Index f = 0; f < dirty_face_.size(); ++f) {
      if (dirty_face_[f] == kClean) continue;
      const Triangle& t = mesh_.triangles[f];
      pool.push_back(Subface::triangle(mesh_.vertices[t[0]], mesh_.vertices[t[1]], mesh_.vertices[t[2]], f));
      pool.back().focused = dirty_face_[f] == kLostCover;
      dirty_face_[f] = kClean;
    }
  }
  std::vector<std::uint32_t> first(pool.size() + 1, 0);  // no ball known yet
  return {.pieces = std::move(pool), .first = std::move(first)};
}

// Darts land in the pool in proportion to measure until kMissLimit land in a row where balls
// already cover, and at least one per piece (Ebeida et al.'s MPS throws in proportion to the
// active cells too). Stopping at the first run of misses leaves most pieces of a pool of many
// small ones (each face of a finely tessellated or smoothed surface starts as one) without a dart,
// and the pool then grows four times a level: the smoothed igl_camelhead held 44 million pieces
// after four levels and was refused as a refinement that cannot converge; one dart a piece kept
// its largest pool at 6.4 million, and cgal_bones's at 0.46 million instead of 3.0.
void BallRefinement::Impl::throw_darts(StratumType type, const std::vector<Subface>& pool, std::string_view phase) {
  std::vector<double> prefix(pool.size());
  double total = 0;
  for (std::size_t i = 0; i < pool.size(); ++i) prefix[i] = total += pool[i].measure();
  if (!(total > 0)) return;
  for (std::size_t misses = 0, thrown = 0; misses < kMissLimit || thrown < pool.size(); ++thrown) {
    const double u = unit_(rng_) * total;
    const std::size_t i = std::min<std::size_t>(std::upper_bound(prefix.begin(), prefix.end(), u) - prefix.begin(), pool.size() - 1);
    const Point p = pool[i].random_point(rng_, unit_);
    misses = try_dart(type, site_on(pool[i], p)) ? 0 : misses + 1;
    if ((stats_.darts & 1023) == 0) report(phase, -1);
  }
}

// One level of the pool: every piece splits, and a child stays where it is still needed and not
// covered. The pieces are tested in parallel against the radii as they stand, which no test
// changes. The balls found violating C1 shrink afterwards, in pool order, and the pieces that
// found them stay in the pool to be tested again, so the result does not depend on the thread
// count. (Cover that a shrinking ball gave up elsewhere is lost cover, sampled in a later pass.)
Pool BallRefinement::Impl::subdivide(StratumType type, const Pool& pool, bool last_level, const LostRegions& lost) {
  struct Outcome {
    std::uint8_t kept = 0;  // bit k: child k stays
    bool abandoned = false;  // at the last level: the piece itself is not covered
    std::vector<Shrink> violations;
    std::vector<std::uint32_t> reaching;  // the kept children's balls, one after the other
    std::array<std::uint32_t, 4> reaching_count{};
  };
  std::vector<Outcome> outcomes(pool.pieces.size());
  // The balls that came since the pool was made, in a tree of their own: in the tree of all balls
  // the old balls' radii bound every subtree, and a query visits far more of it. A pool just made
  // knows no ball yet: its pieces ask the index of all balls, which costs a pass that samples a
  // few pieces far less than a tree of every ball would (a quarter million on cgal_bones).
  geometry::BallTree fresh;
  if (pool.known > 0) {
    for (std::uint32_t b = pool.known; b < balls_.size(); ++b) fresh.insert(balls_[b].site.position, balls_[b].radius, b);
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pool.pieces.size(), 256), [&](const auto& range) {
    std::vector<std::uint32_t> found;
    std::vector<Candidate> candidates;
    std::vector<CoverBall> cover;
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      if (last_level) {
        // Split no further: the piece is counted if it is still bare.
        const Subface& piece = pool.pieces[i];
        if (!(piece.measure() > 0) || !lost.meets(piece)) continue;
        reaching(pool, i, fresh, found);
        classify(type, piece, found, candidates);
        outcomes[i].abandoned = !covers(piece, candidates, cover);
        continue;
      }
      const auto children = pool.pieces[i].split();
      std::uint8_t wanted = 0;  // children of some size that meet a region given up
      for (std::size_t k = 0; k < children.size(); ++k) {
        if (children[k].measure() > 0 && lost.meets(children[k])) wanted |= 1 << k;
      }
      if (wanted == 0) continue;
      reaching(pool, i, fresh, found);
      classify(type, pool.pieces[i], found, candidates);
      Outcome& outcome = outcomes[i];
      for (std::size_t k = 0; k < children.size(); ++k) {
        const Subface& child = children[k];
        if (!(wanted >> k & 1)) continue;
        const std::size_t found_before = outcome.violations.size();
        if (covers(child, candidates, cover)) {
          find_violations(child, candidates, outcome.violations);
          if (outcome.violations.size() == found_before) continue;
        }
        outcome.kept |= 1 << k;
        const Point centroid = child.centroid();
        const double reach = child.circumradius(centroid);
        for (const Candidate& c : candidates) {
          if ((c.centre - centroid).squaredNorm() < (c.radius + reach) * (c.radius + reach)) {
            outcome.reaching.push_back(c.ball);
            ++outcome.reaching_count[k];
          }
        }
      }
    }
  });
  Pool next;
  next.known = static_cast<std::uint32_t>(balls_.size());
  next.pieces.reserve(pool.pieces.size() * 2);
  for (std::size_t i = 0; i < pool.pieces.size(); ++i) {
    const Outcome& outcome = outcomes[i];
    for (const Shrink& v : outcome.violations) shrink(v.ball, v.radius, Reason::C1);
    if (outcome.abandoned) {
      ++stats_.bare_pieces;
      stats_.bare_measure[pool.pieces[i].is_segment() ? 0 : 1] += pool.pieces[i].measure();
    }
    if (outcome.kept == 0) continue;
    const auto children = pool.pieces[i].split();
    next.reaching.insert(next.reaching.end(), outcome.reaching.begin(), outcome.reaching.end());
    for (std::size_t k = 0; k < children.size(); ++k) {
      if (!(outcome.kept >> k & 1)) continue;
      next.pieces.push_back(children[k]);
      next.first.push_back(next.first.back() + outcome.reaching_count[k]);
    }
  }
  return next;
}

// Legitimate runs keep well under 10 pieces per input face, but an input dense with small
// features (a coarse scan with a corner at most vertices, surfaces crossing at a shallow angle
// once resolved) holds a few million at its deepest, early on, and shrinks from there. A pool
// that still doubles level after level once its pieces are a 4096th of their element grows along
// a curve no stratum protects, where balls cannot converge (surfaces that cross and were kept
// so, or nearly touch); so does one past the bound that keeps its memory near a gigabyte. The
// work doubles with every level, so a small input is stopped at a pool of 20 pieces per face
// (at least 20 000): a cube pierced by a square took 5 minutes to reach 250 000 pieces.
void BallRefinement::Impl::check_pool_size(const std::vector<Subface>& pool, const std::vector<std::size_t>& sizes) const {
  const std::size_t depth = sizes.size() - 1;
  const std::size_t runaway_pool = std::clamp<std::size_t>(20 * mesh_.num_faces(), 20'000, 250'000);
  bool runaway = pool.size() > runaway_pool && depth >= 12;
  for (std::size_t d = depth; runaway && d + 4 > depth; --d) runaway = sizes[d] >= 1.8 * static_cast<double>(sizes[d - 1]);
  if (!runaway && pool.size() <= std::max<std::size_t>(8'000'000, 60 * mesh_.num_faces())) return;
  // The face the pieces crowd on most is where the balls cannot converge; the first piece may lie
  // anywhere (on igl_camelhead a whole head's width from the mouth's crevice, where they crowd).
  std::vector<std::size_t> pieces_on(mesh_.num_faces(), 0);
  for (const Subface& piece : pool) {
    ++pieces_on[piece.is_segment() ? strata_.topology.faces_of(piece.element)[0] : piece.element];
  }
  const auto face = static_cast<Index>(std::max_element(pieces_on.begin(), pieces_on.end()) - pieces_on.begin());
  throw Error(Error::Kind::InvalidGeometry,
              "refinement cannot converge: " + std::to_string(pool.size()) + " pieces of the surface stay " +
                  "uncovered after " + std::to_string(depth) + " subdivisions, crowding most on " +
                  describe_face(mesh_, face) + " (" + std::to_string(pieces_on[face]) + " pieces) near " +
                  describe_point(face_centroid(mesh_, face)) + "; surfaces that intersect or nearly touch are the usual cause",
              {.face = face});
}

// Where a ball of a lower type shrank, the pieces of this pass may have lost the cover that kept
// them near a crease or corner, which no ball of this type can give: they would split without end.
// They leave the pass instead, their elements marked, and the pass after the lower phase has
// restored its cover takes them up (the phase loop recurses there, paper 2.3).
void BallRefinement::Impl::defer_lost_lower_cover(Pool& pool) {
  if (lost_lower_.empty()) return;
  const geometry::BoxTree lost(lost_lower_, [&] {
    std::vector<std::uint32_t> items(lost_lower_.size());
    for (std::uint32_t i = 0; i < items.size(); ++i) items[i] = i;
    return items;
  }());
  lost_lower_.clear();
  Pool kept;
  kept.known = pool.known;
  for (std::size_t i = 0; i < pool.pieces.size(); ++i) {
    const Subface& piece = pool.pieces[i];
    geometry::Box box;
    for (int k = 0; k < piece.corner_count(); ++k) box.include(piece.corner(k));
    bool meets = false;
    lost.for_each_overlap(box, [&](std::uint32_t) { meets = true; });
    if (meets) {
      auto& flags = piece.is_segment() ? dirty_edge_ : dirty_face_;
      flags[piece.element] = std::max(flags[piece.element], kLostCover);
      // The next pass samples an element marked so only where cover was given up, and this piece
      // was never covered at all: all of it must be sampled again, not only the part the lower
      // ball gave up, or the rest stays bare (igl_camelhead: 1.6e-4 of a crease beside a corner
      // whose ball shrank, and the patch beside it then split without end).
      const Point centre = piece.centroid();
      (piece.is_segment() ? lost_edges_ : lost_faces_).push_back({centre, 0.0, 2 * piece.circumradius(centre)});
      continue;
    }
    kept.pieces.push_back(piece);
    kept.reaching.insert(kept.reaching.end(), pool.reaching.begin() + pool.first[i], pool.reaching.begin() + pool.first[i + 1]);
    kept.first.push_back(static_cast<std::uint32_t>(kept.reaching.size()));
  }
  pool = std::move(kept);
}

void BallRefinement::Impl::sample(StratumType type) {
  // Only the lost regions recorded so far can have lost cover; later losses are the next pass's.
  std::vector<LostShell>& lost_shells = type == StratumType::Crease ? lost_edges_ : lost_faces_;
  const LostRegions lost(std::move(lost_shells));
  lost_shells.clear();
  Pool pool = initial_pool(type);
  // Each return of the phase loop to this type is a pass of its own, with its own progress.
  const int pass = ++passes_[static_cast<int>(type)];
  const std::string phase = std::string(type == StratumType::Crease ? "refinement: creases" : "refinement: patches") +
                            (pass > 1 ? ", pass " + std::to_string(pass) : "");
  // Progress: the share of the elements sampled in this pass that have no piece left in the
  // pool. (The remaining area vanishes long before the work does, so it would be a poor guide.)
  std::vector<char> pending(type == StratumType::Crease ? strata_.topology.num_edges() : mesh_.num_faces(), 0);
  const std::size_t initial_elements = pool.pieces.size();
  sampling_type_ = static_cast<int>(type);
  lost_lower_.clear();
  std::vector<std::size_t> sizes{pool.pieces.size()};
  stats_.largest_pool = std::max(stats_.largest_pool, pool.pieces.size());
  for (int depth = 0; !pool.pieces.empty(); ++depth) {
    std::size_t elements = 0;
    for (const Subface& piece : pool.pieces) elements += !pending[piece.element] && (pending[piece.element] = 1);
    for (const Subface& piece : pool.pieces) pending[piece.element] = 0;
    report(phase, initial_elements > 0 ? 1.0 - static_cast<double>(elements) / initial_elements : -1);
    throw_darts(type, pool.pieces, phase);
    ++stats_.subdivisions;
    pool = subdivide(type, pool, depth + 1 >= kMaxDepth, lost);
    defer_lost_lower_cover(pool);
    sizes.push_back(pool.pieces.size());
    stats_.largest_pool = std::max(stats_.largest_pool, pool.pieces.size());
    check_pool_size(pool.pieces, sizes);
  }
  sampling_type_ = 3;
}

// C3 within one stratum type. New patch and crease balls keep it (initial_radius and
// shrink_neighbours_for_lipschitz), and shrinking for C3 keeps it too; only corner balls, placed
// without it, and balls shrunk for other reasons can break it. Each such ball p, in turn, shrinks
// to the bound the others set, min_q (r_q + L |p - q|), and then shrinks the balls it makes too
// large to r_p + L |p - q|, which is L-Lipschitz in q: no ball needs to shrink twice for p.
void BallRefinement::Impl::enforce_lipschitz(StratumType type) {
  const auto start = Clock::now();
  std::vector<std::uint32_t> unsettled = std::move(unsettled_[static_cast<int>(type)]);
  unsettled_[static_cast<int>(type)].clear();
  std::sort(unsettled.begin(), unsettled.end());
  unsettled.erase(std::unique(unsettled.begin(), unsettled.end()), unsettled.end());
  for (std::uint32_t p : unsettled) {
    shrink(p, balls_.lipschitz_bound(type, balls_[p].site.position, options_.lipschitz), Reason::C3);
    shrink_neighbours_for_lipschitz(p);
  }
  stats_.c3_seconds += seconds_since(start);
}

// C1 and C2 over dense samples: a ball holding a sample it is not co-smooth with shrinks to
// 0.49 of the distance to the nearest such sample; two overlapping balls neither of which is
// co-smooth with the other's centre both shrink apart.
// Only the balls added since the last sweep can break C1 or C2: an older ball was swept at its
// radius then, and radii only shrink, which makes no ball reach a sample or another ball it did
// not reach before. So a new ball is checked against every ball, and an older one only against the
// new ones, each such pair shrinking both as a sweep of every ball would.
bool BallRefinement::Impl::sweep() {
  const auto start = Clock::now();
  const std::size_t n = balls_.size();
  const std::uint32_t first_new = swept_;
  std::vector<double> target(n);
  for (std::uint32_t b = 0; b < n; ++b) target[b] = balls_[b].radius;
  struct OldPair {
    std::uint32_t ball;
    double radius;
  };
  tbb::enumerable_thread_specific<std::vector<OldPair>> old_pairs;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(first_new, n, 64), [&](const auto& range) {
    std::vector<std::uint32_t> near;
    std::vector<OldPair>& pairs = old_pairs.local();
    for (std::size_t b = range.begin(); b != range.end(); ++b) {
      const RefinedBall& ball = balls_[static_cast<std::uint32_t>(b)];
      double r = ball.radius;
      const double q_star = boundary_.distance_to_non_cosmooth(ball.site, cosmooth_, ball.radius);
      if (q_star < ball.radius) r = kSeparation * q_star;
      for (int t = 0; t < 3; ++t) {
        near.clear();
        balls_.reaching(static_cast<StratumType>(t), ball.site.position, ball.radius, near);
        for (std::uint32_t q : near) {
          const RefinedBall& other = balls_[q];
          if (q == b || cosmooth_(ball.site, other.site) || cosmooth_(other.site, ball.site)) continue;
          const double apart = kSeparation * (other.site.position - ball.site.position).norm();
          r = std::min(r, apart);
          if (q < first_new) pairs.push_back({q, apart});
        }
      }
      target[b] = r;
    }
  });
  for (const std::vector<OldPair>& pairs : old_pairs) {
    for (const OldPair& p : pairs) target[p.ball] = std::min(target[p.ball], p.radius);
  }
  swept_ = static_cast<std::uint32_t>(n);
  const std::size_t before = stats_.c1_shrinks;
  for (std::uint32_t b = 0; b < n; ++b) shrink(b, target[b], Reason::C1);
  stats_.sweep_seconds += seconds_since(start);
  return stats_.c1_shrinks != before;
}

void BallRefinement::Impl::run() {
  int phase = std::min(restart_phase_, 2);
  for (int round = 0;; ++round, ++stats_.rounds) {
    if (round >= options_.max_rounds) {
      stats_.converged = false;
      break;
    }
    const auto start = Clock::now();
    const auto type = static_cast<StratumType>(phase);
    lowest_shrunk_ = 3;
    if (type == StratumType::Corner) {
      report("refinement: corners", -1);
      protect_corners();
      enforce_lipschitz(type);
    } else {
      sample(type);
    }
    stats_.phase_seconds[phase] += seconds_since(start);
    if (lowest_shrunk_ < phase) {  // an earlier phase's ball shrank: recurse to that phase
      phase = lowest_shrunk_;
      continue;
    }
    if (type != StratumType::Corner) {
      enforce_lipschitz(type);
      if (has_dirty(type)) continue;  // shrinking uncovered part of this phase: sample it again
    }
    if (phase < 2) {
      ++phase;
      continue;
    }
    lowest_shrunk_ = 3;
    if (!sweep()) break;
    phase = lowest_shrunk_;
  }
  restart_phase_ = 3;
  for (int t = 0; t < 3; ++t) stats_.balls[t] = 0;
  for (const RefinedBall& b : balls_.balls()) ++stats_.balls[static_cast<int>(b.site.type)];
}

BallRefinement::BallRefinement(const SurfaceMesh& mesh, const Strata& strata, const SizingField& sizing,
                               const RefinementOptions& options, const ProgressCallback& progress,
                               RefinementStats& stats) {
  const auto start = Clock::now();
  impl_ = std::make_unique<Impl>(mesh, strata, sizing, options, progress, stats);
  stats.setup_seconds += seconds_since(start);
}

BallRefinement::~BallRefinement() = default;

void BallRefinement::run() { impl_->run(); }

const BallIndex& BallRefinement::index() const { return impl_->balls(); }

std::vector<Ball> BallRefinement::balls() const {
  std::vector<Ball> out;
  out.reserve(index().size());
  for (const RefinedBall& b : index().balls()) out.push_back({b.site.position, b.radius, b.site.type, b.site.stratum});
  return out;
}

void BallRefinement::shrink_for_slivers(std::uint32_t ball, double radius) { impl_->shrink_for_slivers(ball, radius); }

void BallRefinement::shrink_for_skinny_triangle(std::uint32_t ball, double radius) {
  impl_->shrink_for_skinny_triangle(ball, radius);
}

void BallRefinement::relax_deep_coverage() { impl_->relax_deep_coverage(); }

double BallRefinement::deep_coverage() const { return impl_->deep_coverage(); }

std::vector<Ball> refine_balls(const SurfaceMesh& mesh, const Strata& strata, const SizingField& sizing,
                               const RefinementOptions& options, const ProgressCallback& progress,
                               RefinementStats& stats) {
  BallRefinement refinement(mesh, strata, sizing, options, progress, stats);
  refinement.run();
  return refinement.balls();
}

}  // namespace vorocrust
