// Synthetic seed sets for the cells, export and quality tests and the benchmarks: cubic lattices
// of unit spacing, jittered or not, and the body- and face-centred cubic lattices, labelled by a
// function of position.
#pragma once

#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "vorocrust/seeds.hpp"

namespace vorocrust::test {

// n^3 seeds at integer points 0..n-1, each moved by up to `jitter` along every axis (uniform,
// from `rng_seed`), labelled region(position).
inline std::vector<Seed> lattice_seeds(int n, double jitter, const std::function<std::int32_t(const Point&)>& region,
                                       unsigned rng_seed = 1) {
  std::mt19937_64 rng(rng_seed);
  std::uniform_real_distribution<double> shift(-jitter, jitter);
  std::vector<Seed> seeds;
  seeds.reserve(static_cast<std::size_t>(n) * n * n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        Seed s;
        s.position = Point(i, j, k);
        if (jitter > 0) s.position += Point(shift(rng), shift(rng), shift(rng));
        s.region = region(s.position);
        s.kind = s.region == kOutsideRegion ? SeedKind::Outside : SeedKind::Interior;
        s.radius = 0.5;
        seeds.push_back(s);
      }
    }
  }
  return seeds;
}

// The points of the unit cubic lattice 0..n-1 with the cell offsets `basis` added: the
// body-centred (BCC) lattice with the offsets {0, (1/2, 1/2, 1/2)}, the face-centred (FCC) one
// with {0, (1/2, 1/2, 0), (1/2, 0, 1/2), (0, 1/2, 1/2)}. Labelled region(position), unjittered.
inline std::vector<Seed> centred_lattice_seeds(int n, const std::vector<Point>& basis,
                                               const std::function<std::int32_t(const Point&)>& region) {
  std::vector<Seed> seeds;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        for (const Point& offset : basis) {
          Seed s;
          s.position = Point(i, j, k) + offset;
          s.region = region(s.position);
          s.kind = s.region == kOutsideRegion ? SeedKind::Outside : SeedKind::Interior;
          s.radius = 0.5;
          seeds.push_back(s);
        }
      }
    }
  }
  return seeds;
}

inline std::vector<Seed> bcc_seeds(int n, const std::function<std::int32_t(const Point&)>& region) {
  return centred_lattice_seeds(n, {Point::Zero(), Point(0.5, 0.5, 0.5)}, region);
}

inline std::vector<Seed> fcc_seeds(int n, const std::function<std::int32_t(const Point&)>& region) {
  return centred_lattice_seeds(n, {Point::Zero(), Point(0.5, 0.5, 0), Point(0.5, 0, 0.5), Point(0, 0.5, 0.5)},
                               region);
}

// Material 1 inside the ball of radius r about c, outside elsewhere.
inline std::function<std::int32_t(const Point&)> ball_region(Point c, double r) {
  return [=](const Point& p) { return (p - c).norm() < r ? kInsideRegion : kOutsideRegion; };
}

// Inside the box [lo, hi]^3: material 1 below x = split, material 2 above; outside elsewhere.
inline std::function<std::int32_t(const Point&)> split_box_region(double lo, double hi, double split) {
  return [=](const Point& p) {
    if ((p.array() < lo).any() || (p.array() > hi).any()) return kOutsideRegion;
    return p.x() < split ? std::int32_t{1} : std::int32_t{2};
  };
}

}  // namespace vorocrust::test
