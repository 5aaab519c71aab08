// Internal: the growing set of balls, with one k-d tree of centres per stratum type (paper A.3,
// A.4). Balls are only ever added or shrunk, never moved, so the trees index centres once.
#pragma once

#include <memory>
#include <vector>

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

  // The ball of `type` whose centre is nearest to `p`, or -1 when there is none.
  std::int64_t nearest(StratumType type, const Point& p) const;
  // Balls of `type` with centres strictly within `distance` of `p` (appended to `out`).
  void centres_within(StratumType type, const Point& p, double distance, std::vector<std::uint32_t>& out) const;
  // Balls of `type` that reach within `margin` of `p` (|p - centre| < radius + margin); with
  // margin 0, the balls containing p (A.4).
  void reaching(StratumType type, const Point& p, double margin, std::vector<std::uint32_t>& out) const;
  // Balls of `type` too large beside a ball (p, radius) for C3: r_q > radius + L |p - q|.
  void lipschitz_violators(StratumType type, const Point& p, double radius, double L,
                           std::vector<std::uint32_t>& out) const;

 private:
  // Paper A.3/A.4 bound neighbourhoods through the Lipschitz condition, which holds only after it
  // is enforced. Instead each type's balls are also filed by radius class [2^k, 2^(k+1)): a
  // search per class with radius 2^(k+1) + margin finds every reaching ball at any time, and
  // stays local because radii vary slowly.
  struct Trees;
  void file_in_class(std::uint32_t ball);
  std::vector<RefinedBall> balls_;
  std::vector<std::pair<int, std::uint32_t>> class_slot_;  // per ball: radius class, index in it
  std::unique_ptr<Trees> trees_;
};

}  // namespace vorocrust
