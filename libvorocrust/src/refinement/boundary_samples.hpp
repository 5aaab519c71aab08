// Internal: the boundary k-d trees of paper appendix A.1 and the filtered nearest-point query of
// A.2. The input is supersampled — corners exactly, creases and patches densely (random points in
// proportion to length or area, plus every element's midpoint or centroid and points near its
// corners, so no element is missed) — and each sample carries its SurfaceSite. Patch samples are
// filed by face, which lets the filtered query pass over faces that cannot hold a sample it wants.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include "refinement/surface_site.hpp"

namespace vorocrust {

// Random samples over all creases and all patches (A.1). The paper takes 10^5 and 10^6 for any
// model; here they scale with the number of elements within those bounds, since every element
// also gets its own fixed samples and small models need far fewer.
struct BoundarySampleCounts {
  std::size_t crease_per_edge = 100, crease_min = 20'000, crease_max = 100'000;
  std::size_t patch_per_face = 300, patch_min = 100'000, patch_max = 1'000'000;
};

class BoundarySamples {
 public:
  BoundarySamples(const SurfaceMesh& mesh, const Strata& strata, const BoundarySampleCounts& counts,
                  std::uint64_t seed);
  ~BoundarySamples();

  // Distance from `center` to the nearest sample that is not co-smooth with it (A.2): the
  // estimate of |p - q*| in the radius rule r_p <= 0.49 |p - q*|. Samples at `limit` or beyond
  // are not looked at (the radius rule has a smaller bound already); returns `limit` then.
  double distance_to_non_cosmooth(const SurfaceSite& center, const CoSmoothness& cosmooth,
                                  double limit = std::numeric_limits<double>::infinity()) const;

  std::size_t size() const;

 private:
  void add_crease_samples(const SurfaceMesh& mesh, const Strata& strata, const BoundarySampleCounts& counts,
                          std::mt19937_64& rng, std::uniform_real_distribution<double>& unit);
  void add_patch_samples(const SurfaceMesh& mesh, const Strata& strata, const BoundarySampleCounts& counts,
                         std::uint64_t seed);
  // Lowers `best` (a squared distance) to that of the nearest patch sample not co-smooth with center.
  void nearest_non_cosmooth_patch_sample(const SurfaceSite& center, const CoSmoothness& cosmooth, double& best) const;

  struct Trees;
  std::vector<SurfaceSite> sites_[2];  // corner and crease samples
  std::vector<Point> patch_points_;    // patch samples, by face (their sites differ only in position)
  std::unique_ptr<Trees> trees_;
};

}  // namespace vorocrust
