// Internal: the growing set of balls, with one tree of balls per stratum type (paper A.3, A.4).
// Balls are only ever added or shrunk, never moved, so the trees index centres once.
#pragma once

#include <memory>
#include <vector>

#include "geometry/ball_tree.hpp"
#include "refinement/surface_site.hpp"

namespace vorocrust {

struct RefinedBall {
  SurfaceSite site;  // the centre, on the input surface
  double radius = 0;
};

class BallIndex {
 public:
  BallIndex();
  ~BallIndex();

  std::uint32_t add(const SurfaceSite& site, double radius);
  std::size_t size() const { return balls_.size(); }
  const RefinedBall& operator[](std::uint32_t i) const { return balls_[i]; }
  const std::vector<RefinedBall>& balls() const { return balls_; }
  // Radii only shrink: shrinking is how every violation is resolved.
  void shrink(std::uint32_t i, double radius);

  // min over the balls q of `type` of r_q + L |p - q|: the largest radius a ball at p may have
  // under C3 (infinity when the type has no ball).
  double lipschitz_bound(StratumType type, const Point& p, double L) const;
  // Balls of `type` with centres strictly within `distance` of `p` (appended to `out`).
  void centres_within(StratumType type, const Point& p, double distance, std::vector<std::uint32_t>& out) const;
  // Balls of `type` that reach within `margin` of `p` (|p - centre| < radius + margin); with
  // margin 0, the balls containing p (A.4). Only balls numbered `first` or later, if given.
  void reaching(StratumType type, const Point& p, double margin, std::vector<std::uint32_t>& out,
                std::uint32_t first = 0) const;
  // Balls of `type` whose radius scaled by `scale` reaches within `margin` of `p`.
  void reaching_scaled(StratumType type, const Point& p, double scale, double margin,
                       std::vector<std::uint32_t>& out) const;
  // Whether some ball of any type, its radius scaled by `scale`, holds p strictly inside.
  bool covers(const Point& p, double scale = 1) const;
  // Balls of `type` too large beside a ball (p, radius) for C3: r_q > radius + L |p - q|.
  void lipschitz_violators(StratumType type, const Point& p, double radius, double L,
                           std::vector<std::uint32_t>& out) const;

 private:
  std::vector<RefinedBall> balls_;
  std::unique_ptr<geometry::BallTree[]> trees_;  // one per stratum type
};

}  // namespace vorocrust
