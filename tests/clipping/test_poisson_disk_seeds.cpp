// Maximal Poisson-disk seeds on built domains: the disk condition over every pair, maximality by
// sampling the volume, the same seeds for the same random seed and others for another.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "clipping/poisson_disk_seeds.hpp"
#include "surface_builder.hpp"
#include "vorocrust/regions.hpp"

namespace vorocrust {
namespace {

SurfaceMesh box(const Point& lo, const Point& hi) {
  test::SurfaceBuilder b;
  b.box(lo, hi);
  label_regions(b.mesh);
  return b.mesh;
}

double nearest(const std::vector<Seed>& seeds, const Point& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const Seed& s : seeds) best = std::min(best, (s.position - p).norm());
  return best;
}

TEST(PoissonDiskSeeds, AreAtLeastRApartAndLeaveNoGap) {
  const double r = 0.12;
  const SurfaceMesh domain = box(Point::Zero(), Point(1, 0.6, 0.5));
  const std::vector<Seed> seeds = clipping::poisson_disk_seeds(domain, 1, r, 4);
  ASSERT_GT(seeds.size(), 100u);
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    EXPECT_EQ(seeds[i].region, 1);
    EXPECT_TRUE((seeds[i].position.array() > 0).all() &&
                (seeds[i].position.array() < Point(1, 0.6, 0.5).array()).all());
    for (std::size_t j = i + 1; j < seeds.size(); ++j) ASSERT_GE((seeds[i].position - seeds[j].position).norm(), r);
  }
  std::mt19937_64 random(2);
  std::uniform_real_distribution<double> u(0, 1);
  int beyond = 0;
  double worst = 0;
  for (int k = 0; k < 20000; ++k) {
    const double d = nearest(seeds, Point(u(random), 0.6 * u(random), 0.5 * u(random)));
    worst = std::max(worst, d);
    beyond += d > r;
  }
  EXPECT_LT(worst, 1.02 * r);
  EXPECT_LT(beyond, 20);
}

TEST(PoissonDiskSeeds, FollowTheRandomSeed) {
  const SurfaceMesh domain = box(Point::Zero(), Point::Ones());
  const auto a = clipping::poisson_disk_seeds(domain, 1, 0.2, 1), b = clipping::poisson_disk_seeds(domain, 1, 0.2, 1);
  const auto c = clipping::poisson_disk_seeds(domain, 1, 0.2, 2);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].position, b[i].position);
  EXPECT_NE(a.front().position, c.front().position);
}

TEST(PoissonDiskSeeds, OutsideSeedsKeepOffTheMaterial) {
  const SurfaceMesh domain = box(Point::Zero(), Point::Ones());
  for (const Seed& s : clipping::outside_seeds(domain, 0.15, 0.1)) {
    EXPECT_EQ(s.region, kOutsideRegion);
    EXPECT_GE((s.position - s.position.cwiseMax(0.0).cwiseMin(1.0)).norm(), 0.15 - 1e-12);
  }
}

}  // namespace
}  // namespace vorocrust
