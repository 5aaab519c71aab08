// The boundary samples (paper A.1, A.2): the nearest sample not co-smooth with a point lies where
// the input says it should, within the spacing of the samples, on a box (creases) and on a torus
// (one curved patch, where the random patch samples decide); and the samples drawn on two threads
// are those drawn on one.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "core/split_mix.hpp"
#include "features/strata.hpp"
#include "refinement/boundary_samples.hpp"
#include "refinement/surface_site.hpp"
#include "test_support.hpp"
#include "vorocrust/read_mesh.hpp"

namespace vorocrust {
namespace {

constexpr double kSharpAngle = M_PI / 6;

// Patch sites at random points of random faces.
std::vector<SurfaceSite> random_sites(const SurfaceMesh& mesh, const Strata& strata, std::size_t count) {
  SplitMix64 random(7);
  std::vector<SurfaceSite> sites;
  for (std::size_t k = 0; k < count; ++k) {
    const Index f = static_cast<Index>(random() % mesh.num_faces());
    const Triangle& t = mesh.triangles[f];
    double u = random.unit(), v = random.unit();
    if (u + v > 1) u = 1 - u, v = 1 - v;
    const Point& a = mesh.vertices[t[0]];
    sites.push_back(patch_site(strata, f, a + u * (mesh.vertices[t[1]] - a) + v * (mesh.vertices[t[2]] - a)));
  }
  return sites;
}

// On the box [1, 2] x [0, 1] x [0, 1], the points nearest to a point of one side that are not
// co-smooth with it lie on the sides across the nearest edge: at the distance to that edge.
TEST(BoundarySamples, NearestNonCosmoothSampleIsAcrossTheNearestEdge) {
  const SurfaceMesh box = read_mesh(test::model("sandia_OneBox.obj"));
  const Strata strata = detect_strata(box, kSharpAngle);
  const CoSmoothness cosmooth(strata, kSharpAngle, 1e-12);
  const BoundarySamples samples(box, strata, BoundarySampleCounts{}, 3);
  double worst_excess = 0;
  for (const SurfaceSite& site : random_sites(box, strata, 400)) {
    const Point& p = site.position;
    // Distance to the nearest edge of the side p lies on: the smallest offset from a face of the
    // box along the two axes in which p is not on a face.
    const Point from_lower = p - Point(1, 0, 0), from_upper = Point(2, 1, 1) - p;
    std::vector<double> offsets;
    for (int axis = 0; axis < 3; ++axis) {
      const double to_face = std::min(from_lower[axis], from_upper[axis]);
      if (to_face > 1e-12) offsets.push_back(to_face);
    }
    ASSERT_EQ(offsets.size(), 2u) << p.transpose();
    const double expected = *std::min_element(offsets.begin(), offsets.end());
    const double found = samples.distance_to_non_cosmooth(site, cosmooth);
    EXPECT_GE(found, expected - 1e-12) << p.transpose();
    worst_excess = std::max(worst_excess, found - expected);
  }
  // 100 000 samples on the six sides, about 130 in every square of side 0.03 there.
  EXPECT_LT(worst_excess, 0.03);
}

// On one curved patch nothing is a crease: whether a point is co-smooth with a site depends on
// where it lies, so faces are partly co-smooth and the random samples of their faces answer. A
// brute force over a fine grid of points on every face is the reference: the query finds a
// sample, a point of the surface, so it can be farther than the nearest point of the grid only by
// about the samples' spacing, and nearer only by the grid's.
TEST(BoundarySamples, NearestNonCosmoothSampleOnACurvedPatchMatchesABruteForce) {
  const SurfaceMesh torus = read_mesh(test::model("sandia_torus.obj"));  // radii 1 and 0.5
  const Strata strata = detect_strata(torus, kSharpAngle);
  ASSERT_EQ(strata.num_patches, 1u);
  ASSERT_TRUE(strata.creases.empty());
  const CoSmoothness cosmooth(strata, kSharpAngle, 1e-12);
  const BoundarySamples samples(torus, strata, BoundarySampleCounts{}, 5);
  constexpr int kGrid = 36;  // points per face edge of the reference grid
  std::vector<SurfaceSite> grid;
  double longest_edge = 0;
  for (Index f = 0; f < torus.num_faces(); ++f) {
    const Triangle& t = torus.triangles[f];
    const Point &a = torus.vertices[t[0]], &b = torus.vertices[t[1]], &c = torus.vertices[t[2]];
    longest_edge = std::max({longest_edge, (b - a).norm(), (c - b).norm(), (a - c).norm()});
    for (int i = 0; i <= kGrid; ++i) {
      for (int j = 0; i + j <= kGrid; ++j) {
        grid.push_back(patch_site(strata, f, a + (i * (b - a) + j * (c - a)) / kGrid));
      }
    }
  }
  double worst_farther = 0, worst_nearer = 0;
  for (const SurfaceSite& site : random_sites(torus, strata, 24)) {
    double reference = std::numeric_limits<double>::infinity();
    for (const SurfaceSite& x : grid) {
      if (!cosmooth(site, x)) reference = std::min(reference, (x.position - site.position).norm());
    }
    ASSERT_TRUE(std::isfinite(reference)) << site.position.transpose();
    const double found = samples.distance_to_non_cosmooth(site, cosmooth);
    worst_farther = std::max(worst_farther, found - reference);
    worst_nearer = std::max(worst_nearer, reference - found);
  }
  // The grid's points lie longest_edge / kGrid apart along an edge; the samples (300 per face at
  // random, and each face's centroid and points near its corners) about a fifteenth of a face's
  // side. (Measured: never farther, at most 5e-6 nearer.)
  EXPECT_LT(worst_nearer, longest_edge / kGrid);
  EXPECT_LT(worst_farther, longest_edge / 10);
  std::printf("torus: longest edge %.4f; the query lies %.2g farther and %.2g nearer than the grid at most\n",
              longest_edge, worst_farther, worst_nearer);
}

TEST(BoundarySamples, TwoThreadsDrawTheSamplesOneDraws) {
  const SurfaceMesh joint = read_mesh(test::model("cgal_joint.off"));
  const Strata strata = detect_strata(joint, kSharpAngle);
  const CoSmoothness cosmooth(strata, kSharpAngle, 1e-12);
  const std::vector<SurfaceSite> sites = random_sites(joint, strata, 300);
  const auto distances = [&](int threads) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    const BoundarySamples samples(joint, strata, BoundarySampleCounts{}, 11);
    std::vector<double> out{static_cast<double>(samples.size())};
    for (const SurfaceSite& site : sites) out.push_back(samples.distance_to_non_cosmooth(site, cosmooth));
    return out;
  };
  EXPECT_EQ(distances(1), distances(2));
}

}  // namespace
}  // namespace vorocrust
