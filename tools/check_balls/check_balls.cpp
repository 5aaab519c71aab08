// The conditions themselves, by brute force over samples and ball pairs (see check_balls.hpp).
//
// Tolerances: every radius comparison has a relative slack of 1e-9 in the balls' favour (a point
// at distance r(1 - 1e-9) is inside for C1, a point at r(1 + 1e-9) still covered for coverage), so
// points exactly on a sphere, where any two implementations may round differently, are never
// called violations. Positions (protection) are compared with 1e-9 times the bounding-box diagonal.
#include "check_balls/check_balls.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "check_balls/ball_sites.hpp"
#include "check_balls/co_smooth.hpp"
#include "check_balls/samples.hpp"
#include "check_balls/sphere_index.hpp"
#include "check_balls/strata.hpp"
#include "check_balls/surface_locator.hpp"
#include "check_balls/violation_log.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust::checker {
namespace {

constexpr double kRelative = 1e-9;
constexpr std::size_t kChunk = 4096;

struct Context {
  const std::vector<CheckedBall>& balls;
  const std::vector<BallSite>& sites;
  const SphereIndex& ball_index;
  const CoSmoothTest& co_smooth;
  double max_radius;
  double alpha;
  double lipschitz;

  SurfacePoint centre(std::size_t i) const { return {balls[i].centre, sites[i].stratum, sites[i].directions}; }
};

// Runs body(begin, end, log) over [0, n) in chunks, in parallel, merging logs in chunk order.
template <class Body>
ViolationLog in_chunks(std::size_t n, std::size_t max_listed, Body&& body) {
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  std::vector<ViolationLog> logs(chunks, ViolationLog(max_listed));
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks), [&](const tbb::blocked_range<std::size_t>& range) {
    for (std::size_t c = range.begin(); c != range.end(); ++c) {
      body(c * kChunk, std::min(n, (c + 1) * kChunk), logs[c]);
    }
  });
  ViolationLog merged(max_listed);
  for (ViolationLog& log : logs) merged.merge(std::move(log));
  return merged;
}

std::string describe_sample(const Sample& s) {
  return format("%s point %s (%s %u)", describe(s.stratum).c_str(), describe(s.position).c_str(),
                to_string(s.source), s.element);
}

std::string why_not(const Context& ctx, CoSmoothness result, const SurfacePoint& p, const SurfacePoint& x) {
  std::string text = to_string(result);
  if (result == CoSmoothness::DirectionAngle) {
    text += format(" (%.4g deg)", ctx.co_smooth.smallest_direction_angle(p, x));
  } else if (result == CoSmoothness::Position) {
    text += format(" (|cos| %.4g)", ctx.co_smooth.position_cosine(p, x));
  }
  return text;
}

// C1, C4a, coverage and crease protection, at every sample.
void check_sample(const Context& ctx, const SampleSet& samples, const Sample& s, ViolationLog& log) {
  const SurfacePoint x{s.position, s.stratum, samples.directions_of(s)};
  bool covered = false, deep = false, exempt = false, protected_by_feature_ball = false;
  double best_depth = std::numeric_limits<double>::infinity();  // min |x - p| / r_p
  std::size_t best_ball = 0;
  ctx.ball_index.for_each_near(x.position, kRelative * ctx.max_radius, [&](Index i, double) {
    const CheckedBall& ball = ctx.balls[i];
    const double d = (x.position - ball.centre).norm();
    if (d > ball.radius * (1 + kRelative)) return;
    covered = true;
    if (d / ball.radius < best_depth) best_depth = d / ball.radius, best_ball = i;
    deep = deep || d <= (1 - ctx.alpha) * ball.radius * (1 + kRelative);
    exempt = exempt || dimension(ball.type) < dimension(x.stratum.type);
    protected_by_feature_ball = protected_by_feature_ball || ball.type != StratumType::Patch;
    if (d >= ball.radius * (1 - kRelative)) return;  // on the sphere, not inside
    const SurfacePoint p = ctx.centre(i);
    const CoSmoothness result = ctx.co_smooth(p, x);
    if (result == CoSmoothness::Yes) return;
    log.add(Condition::C1, i, [&] {
      Violation v;
      v.balls = {i};
      v.point = x.position;
      v.stratum = describe(x.stratum);
      v.message = format("%s on %s contains %s at distance %.6g < r: %s", describe_ball(ctx.balls, i).c_str(),
                         describe(p.stratum).c_str(), describe_sample(s).c_str(), d,
                         why_not(ctx, result, p, x).c_str());
      return v;
    });
  });
  auto sample_violation = [&](const std::string& what) {
    Violation v;
    v.point = x.position;
    v.stratum = describe(x.stratum);
    v.message = describe_sample(s) + " " + what;
    return v;
  };
  if (!covered) {
    log.add(Condition::Coverage, std::nullopt, [&] { return sample_violation("is in no ball"); });
  }
  if (!deep && !exempt) {
    log.add(Condition::C4a, std::nullopt, [&] {
      if (!covered) return sample_violation("is in no ball, so not deeply covered");
      Violation v = sample_violation(format("is not deeply covered: deepest in %s at |x-p|/r %.6g > 1 - alpha %.6g",
                                            describe_ball(ctx.balls, best_ball).c_str(), best_depth, 1 - ctx.alpha));
      v.balls = {best_ball};
      return v;
    });
  }
  if (x.stratum.type == StratumType::Crease && !protected_by_feature_ball) {
    log.add(Condition::Protection, std::nullopt,
            [&] { return sample_violation("is covered by no corner or crease ball"); });
  }
}

// C2 and C4b for the pairs (p, q > p) that overlap; C3 for every q near enough to matter.
void check_ball(const Context& ctx, std::size_t p, ViolationLog& log) {
  const CheckedBall& bp = ctx.balls[p];
  ctx.ball_index.for_each_near(bp.centre, bp.radius * (1 + kRelative), [&](Index q, double) {
    if (q <= p) return;
    const CheckedBall& bq = ctx.balls[q];
    const double d = (bp.centre - bq.centre).norm();
    if (d < (bp.radius + bq.radius) * (1 - kRelative)) {
      const SurfacePoint sp = ctx.centre(p), sq = ctx.centre(q);
      const CoSmoothness q_with_p = ctx.co_smooth(sp, sq);
      const CoSmoothness p_with_q = ctx.co_smooth(sq, sp);
      if (q_with_p != CoSmoothness::Yes && p_with_q != CoSmoothness::Yes) {
        log.add(Condition::C2, p, [&] {
          Violation v;
          v.balls = {p, q};
          v.message = format("%s on %s and %s on %s overlap (|p-q| %.6g < r_p + r_q %.6g), neither centre co-smooth "
                             "with the other: %s; %s",
                             describe_ball(ctx.balls, p).c_str(), describe(sp.stratum).c_str(),
                             describe_ball(ctx.balls, q).c_str(), describe(sq.stratum).c_str(), d,
                             bp.radius + bq.radius, why_not(ctx, q_with_p, sp, sq).c_str(),
                             why_not(ctx, p_with_q, sq, sp).c_str());
          return v;
        });
      }
    }
    const double larger = std::max(bp.radius, bq.radius);
    if (d < (1 - ctx.alpha) * larger * (1 - kRelative)) {
      log.add(Condition::C4b, p, [&] {
        Violation v;
        v.balls = {p, q};
        v.message = format("%s and %s: |p-q| %.6g < (1 - alpha) max(r_p, r_q) %.6g",
                           describe_ball(ctx.balls, p).c_str(), describe_ball(ctx.balls, q).c_str(), d,
                           (1 - ctx.alpha) * larger);
        return v;
      });
    }
  });
  // r_p > r_q + L|p-q| needs |p-q| < r_p / L.
  ctx.ball_index.for_each_near(bp.centre, bp.radius / ctx.lipschitz, [&](Index q, double) {
    const CheckedBall& bq = ctx.balls[q];
    if (q == p || bq.type != bp.type) return;
    const double d = (bp.centre - bq.centre).norm();
    const double bound = bq.radius + ctx.lipschitz * d;
    if (bp.radius <= bound * (1 + kRelative)) return;
    log.add(Condition::C3, p, [&] {
      Violation v;
      v.balls = {p, q};
      v.message = format("%s: r_p %.6g > r_q + L|p-q| %.6g for %s (|p-q| %.6g)", describe_ball(ctx.balls, p).c_str(),
                         bp.radius, bound, describe_ball(ctx.balls, q).c_str(), d);
      return v;
    });
  });
}

}  // namespace

const char* to_string(StratumType type) noexcept {
  switch (type) {
    case StratumType::Corner: return "corner";
    case StratumType::Crease: return "crease";
    case StratumType::Patch: return "patch";
  }
  return "?";
}

const char* to_string(Condition condition) noexcept {
  switch (condition) {
    case Condition::C1: return "C1";
    case Condition::C2: return "C2";
    case Condition::C3: return "C3";
    case Condition::C4a: return "C4a";
    case Condition::C4b: return "C4b";
    case Condition::Coverage: return "coverage";
    case Condition::Protection: return "protection";
  }
  return "?";
}

const char* title(Condition condition) noexcept {
  switch (condition) {
    case Condition::C1: return "smooth coverage";
    case Condition::C2: return "smooth overlaps";
    case Condition::C3: return "Lipschitz radii";
    case Condition::C4a: return "deep coverage of the surface";
    case Condition::C4b: return "deep coverage, centres apart";
    case Condition::Coverage: return "every surface point in a ball";
    case Condition::Protection: return "corners, creases and centres protected";
  }
  return "?";
}

double deep_coverage_alpha() { return 1 - std::sqrt(3.0) / 2; }

void BallCheckOptions::check() const {
  if (!(sharp_angle_degrees > 0 && sharp_angle_degrees < 90)) {
    throw Error(Error::Kind::Usage, format("--sharp-angle must be in (0, 90) degrees, not %g", sharp_angle_degrees));
  }
  if (!(lipschitz > 0 && lipschitz < 1)) {
    throw Error(Error::Kind::Usage, format("--lipschitz must be in (0, 1), not %g", lipschitz));
  }
}

std::size_t BallCheckReport::violations() const {
  std::size_t n = 0;
  for (const ConditionResult& c : conditions) n += c.count;
  return n;
}

BallCheckReport check_balls(const SurfaceMesh& mesh, const std::vector<CheckedBall>& balls,
                            const BallCheckOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  options.check();
  BallCheckReport report;
  report.sharp_angle_degrees = options.sharp_angle_degrees;
  report.lipschitz = options.lipschitz;
  report.alpha = deep_coverage_alpha();
  const double theta = options.sharp_angle_degrees * std::numbers::pi / 180;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const CheckedBall& b = balls[i];
    if (!b.centre.allFinite() || !std::isfinite(b.radius) || !(b.radius > 0)) {
      throw Error(Error::Kind::Usage, format("check-balls: ball %zu needs a finite centre and a positive radius", i));
    }
    ++report.balls_by_type[static_cast<std::size_t>(b.type)];
  }

  if (mesh.vertices.empty() || mesh.triangles.empty()) {
    throw Error(Error::Kind::InvalidGeometry, "check-balls: the surface has no triangles");
  }
  Point low = mesh.vertices.front(), high = low;
  for (const Point& v : mesh.vertices) low = low.cwiseMin(v), high = high.cwiseMax(v);
  report.diagonal = (high - low).norm();
  const double tolerance = kRelative * report.diagonal;

  const Strata strata = find_strata(mesh, theta);
  report.corners = strata.num_corners();
  report.creases = strata.num_creases();
  report.patches = strata.num_patches;

  ViolationLog log(options.max_listed);
  const SurfaceLocator locator(mesh, strata);
  const std::vector<BallSite> sites = locate_balls(mesh, strata, locator, balls, tolerance, log);
  check_corner_balls(mesh, strata, balls, tolerance, log);

  std::vector<Point> centres;
  std::vector<double> radii;
  double max_radius = 0;
  for (const CheckedBall& b : balls) {
    centres.push_back(b.centre), radii.push_back(b.radius);
    max_radius = std::max(max_radius, b.radius);
  }
  const SphereIndex ball_index(centres, radii);
  const CoSmoothTest co_smooth(strata, theta);
  const Context ctx{balls, sites, ball_index, co_smooth, max_radius, report.alpha, options.lipschitz};

  const SampleSet samples = make_samples(mesh, strata, options.face_samples, options.crease_samples, options.seed);
  report.samples = samples.counts;
  const auto each_sample = [&](std::size_t begin, std::size_t end, ViolationLog& out) {
    for (std::size_t i = begin; i < end; ++i) check_sample(ctx, samples, samples.samples[i], out);
  };
  const auto each_ball = [&](std::size_t begin, std::size_t end, ViolationLog& out) {
    for (std::size_t p = begin; p < end; ++p) check_ball(ctx, p, out);
  };
  log.merge(in_chunks(samples.samples.size(), options.max_listed, each_sample));
  log.merge(in_chunks(balls.size(), options.max_listed, each_ball));

  log.write_to(report);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace vorocrust::checker
