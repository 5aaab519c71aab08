// Ball neighbourhoods (paper appendix A.3, A.4).
#include "refinement/ball_index.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vorocrust {

BallIndex::BallIndex() : trees_(std::make_unique<geometry::BallTree[]>(3)) {}
BallIndex::~BallIndex() = default;

std::uint32_t BallIndex::add(const SurfaceSite& site, double radius) {
  const auto id = static_cast<std::uint32_t>(balls_.size());
  balls_.push_back({site, radius});
  trees_[static_cast<int>(site.type)].insert(site.position, radius, id);
  return id;
}

void BallIndex::shrink(std::uint32_t i, double radius) {
  if (!(radius < balls_[i].radius)) return;
  balls_[i].radius = radius;
  trees_[static_cast<int>(balls_[i].site.type)].shrink(i, radius);
}

double BallIndex::lipschitz_bound(StratumType type, const Point& p, double L) const {
  return trees_[static_cast<int>(type)].lipschitz_bound(p, L);
}

void BallIndex::centres_within(StratumType type, const Point& p, double distance, std::vector<std::uint32_t>& out) const {
  const double limit = distance * distance;
  trees_[static_cast<int>(type)].search(
      p, [&](double d2, double, std::uint32_t) { return d2 < limit; },
      [&](const geometry::BallTree::Sphere& s) {
        if ((s.centre - p).squaredNorm() < limit) out.push_back(s.ball);
      });
}

void BallIndex::reaching(StratumType type, const Point& p, double margin, std::vector<std::uint32_t>& out,
                         std::uint32_t first) const {
  trees_[static_cast<int>(type)].search(
      p,
      [&](double d2, double max_radius, std::uint32_t newest) {
        return newest >= first && d2 < (max_radius + margin) * (max_radius + margin);
      },
      [&](const geometry::BallTree::Sphere& s) {
        if (s.ball >= first && (s.centre - p).squaredNorm() < (s.radius + margin) * (s.radius + margin)) out.push_back(s.ball);
      });
}

void BallIndex::reaching_scaled(StratumType type, const Point& p, double scale, double margin,
                                std::vector<std::uint32_t>& out) const {
  trees_[static_cast<int>(type)].search(
      p,
      [&](double d2, double max_radius, std::uint32_t) {
        return d2 < (scale * max_radius + margin) * (scale * max_radius + margin);
      },
      [&](const geometry::BallTree::Sphere& s) {
        if ((s.centre - p).squaredNorm() < (scale * s.radius + margin) * (scale * s.radius + margin)) out.push_back(s.ball);
      });
}

bool BallIndex::covers(const Point& p, double scale) const {
  for (int type = 0; type < 3; ++type) {
    if (trees_[type].contains(p, scale)) return true;
  }
  return false;
}

void BallIndex::lipschitz_violators(StratumType type, const Point& p, double radius, double L,
                                    std::vector<std::uint32_t>& out) const {
  // A subtree can hold a violator only if its largest radius exceeds radius + L * (its distance).
  trees_[static_cast<int>(type)].search(
      p,
      [&](double d2, double max_radius, std::uint32_t) {
        return max_radius > radius && L * L * d2 < (max_radius - radius) * (max_radius - radius);
      },
      [&](const geometry::BallTree::Sphere& s) {
        if (s.radius > radius + L * (s.centre - p).norm()) out.push_back(s.ball);
      });
}

}  // namespace vorocrust
