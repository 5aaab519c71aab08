// Balls on the top of a cube and seeds on their spheres: the setting of the tests of the seeds
// placed on spheres (interior/cap_seeds, cells/repair_seeds).
#pragma once

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "interior/cap_seeds.hpp"
#include "refinement/ball_index.hpp"
#include "seeds/locate_regions.hpp"
#include "surface_builder.hpp"

namespace vorocrust::test {

inline constexpr double kRadius = 0.2;

// Balls centred on the top of the cube [-1, 1]^3, the inside below them, and the inner seeds
// each ball's cap holds.
struct TopOfCube {
  SurfaceMesh surface;
  BallIndex balls;
  std::vector<Seed> seeds;

  TopOfCube() {
    test::SurfaceBuilder b;
    b.box(Point(-1, -1, -1), Point(1, 1, 1));
    surface = std::move(b.mesh);
  }
  std::uint32_t ball(double x) {
    SurfaceSite site;
    site.position = Point(x, 0, 1);
    site.direction = Point(0, 0, 1);
    return balls.add(site, kRadius);
  }
  // A seed of `region` on ball b's sphere, `polar` degrees from straight down, at `azimuth`.
  void seed(std::uint32_t b, double polar, double azimuth, std::int32_t region = kInsideRegion) {
    const double t = polar * std::numbers::pi / 180, f = azimuth * std::numbers::pi / 180;
    const Point u(std::sin(t) * std::cos(f), std::sin(t) * std::sin(f), -std::cos(t));
    seeds.push_back(Seed{balls[b].site.position + kRadius * u, region, kRadius, SeedKind::Surface});
  }
  // Eight inner seeds 70 degrees from straight down: their middle is 1.15 radii from each.
  void ring(std::uint32_t b) {
    for (int k = 0; k < 8; ++k) seed(b, 70, 45 * k);
  }
  std::vector<Seed> poles() const { return pole_seeds(seeds, balls, RegionLocator(surface)); }
};

}  // namespace vorocrust::test
