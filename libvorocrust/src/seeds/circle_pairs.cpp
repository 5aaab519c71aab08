// Seed pairs where consecutive circles meet, and seeds in the wide gaps of corner circles
// (paper 2.4 and 2.6).
#include "seeds/circle_pairs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/plane_tree.hpp"

namespace vorocrust::seeds {

namespace {

constexpr double kWideGap = 2 * std::numbers::pi / 3;
constexpr double kGapSpacing = std::numbers::pi / 2;

}  // namespace

PlaneBoundarySeeds circle_pairs(const refinement::PlaneProtection& protection) {
  const std::vector<PlaneCircle>& circles = protection.circles;
  PlaneBoundarySeeds out;
  std::vector<std::vector<double>> angles(circles.size());  // of the seeds on each corner circle
  const auto on = [&](std::uint32_t c, const Point2& p) {
    if (circles[c].corner) {
      const Point2 d = p - circles[c].centre;
      angles[c].push_back(std::atan2(d.y(), d.x()));
    }
  };
  for (const auto& [i, j, chain] : protection.pairs) {
    std::array<Point2, 2> meet;
    if (!refinement::circles_meet(circles[i], circles[j], meet)) {
      throw Error(Error::Kind::Internal, "consecutive circles do not meet after refinement");
    }
    const double radius = (circles[i].radius + circles[j].radius) / 2;
    const auto first = static_cast<std::uint32_t>(out.seeds.size());
    for (const Point2& p : meet) {
      out.seeds.push_back({Point(p.x(), p.y(), 0), kOutsideRegion, radius, SeedKind::Surface});
      on(i, p);
      on(j, p);
    }
    out.twin.push_back(first + 1);
    out.twin.push_back(first);
    const std::array<std::int32_t, 2> both{static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)};
    out.on_circles.insert(out.on_circles.end(), {both, both});
  }
  std::vector<Point2> centres;
  double largest = 0;
  for (const PlaneCircle& c : circles) {
    centres.push_back(c.centre);
    largest = std::max(largest, c.radius);
  }
  const geometry::PlaneTree tree(centres);
  std::vector<std::uint32_t> near;
  const auto covered = [&](std::uint32_t own, const Point2& p) {
    tree.within(p, refinement::kCoverMargin * largest, near);
    return std::any_of(near.begin(), near.end(), [&](std::uint32_t q) {
      return q != own && (p - centres[q]).norm() < refinement::kCoverMargin * circles[q].radius;
    });
  };
  for (std::uint32_t c = 0; c < circles.size(); ++c) {
    std::vector<double>& a = angles[c];
    if (a.empty()) continue;
    std::sort(a.begin(), a.end());
    for (std::size_t k = 0; k < a.size(); ++k) {
      const double from = a[k], gap = (k + 1 < a.size() ? a[k + 1] : a[0] + 2 * std::numbers::pi) - from;
      if (gap <= kWideGap) continue;
      const int count = std::max(1, static_cast<int>(std::ceil(gap / kGapSpacing)) - 1);
      for (int m = 1; m <= count; ++m) {
        const double t = from + gap * m / (count + 1);
        const Point2 p = circles[c].centre + circles[c].radius * Point2(std::cos(t), std::sin(t));
        if (covered(c, p)) continue;
        out.twin.push_back(static_cast<std::uint32_t>(out.seeds.size()));
        out.on_circles.push_back({static_cast<std::int32_t>(c), -1});
        out.seeds.push_back({Point(p.x(), p.y(), 0), kOutsideRegion, circles[c].radius, SeedKind::Cap});
      }
    }
  }
  return out;
}

}  // namespace vorocrust::seeds
