// Test support for the clipping tests: a box as a labelled domain, and the clipped cells of seeds
// inside it bounded by outside seeds a spacing of 1.5 beyond it.
#pragma once

#include <vector>

#include "clipping/clip_cells.hpp"
#include "surface_builder.hpp"
#include "vorocrust/regions.hpp"
#include "vorocrust/seeds.hpp"

namespace vorocrust::test {

inline SurfaceMesh labelled_box(const Point& lo, const Point& hi) {
  SurfaceBuilder b;
  b.box(lo, hi);
  SurfaceMesh surface = b.mesh;
  label_regions(surface);
  return surface;
}

// `inside` (material seeds) followed by outside seeds on a box 1.5 beyond [lo, hi].
inline std::vector<Seed> with_outside_seeds(std::vector<Seed> inside, const Point& lo, const Point& hi) {
  const Point a = lo - Point::Constant(1.5), b = hi + Point::Constant(1.5);
  const int k = 8;
  for (int i = 0; i <= k; ++i) {
    for (int j = 0; j <= k; ++j) {
      for (int l = 0; l <= k; ++l) {
        if (i != 0 && i != k && j != 0 && j != k && l != 0 && l != k) continue;
        inside.push_back({a + (b - a).cwiseProduct(Point(i, j, l) / k), 0, 0, SeedKind::Outside});
      }
    }
  }
  return inside;
}

inline std::vector<Seed> interior_seeds(const std::vector<Point>& points) {
  std::vector<Seed> seeds;
  for (const Point& p : points) seeds.push_back({p, 1, 0, SeedKind::Interior});
  return seeds;
}

// The clipped cells of `inside` in the box [lo, hi].
inline VoronoiMesh clipped_in_box(const std::vector<Seed>& inside, const Point& lo, const Point& hi) {
  return clipping::clip_cells(clipping::material_diagrams(with_outside_seeds(inside, lo, hi), inside.size()),
                              labelled_box(lo, hi));
}

}  // namespace vorocrust::test
