// Internal: the interior seeds of a 2D domain (paper 2.5, 2.6), over the whole frame round it;
// which of them lie in a material is found from the cells.
//
// The spacing at x is the Lipschitz extension of the circles' radii, min over circles of
// r + L |x - c|, bounded by the sizing field. Seeds keep that spacing from every seed and stay
// outside every circle by kClearance of its radius. Random: a maximal Poisson-disk sample grown
// from the boundary seeds (Bridson's dart throwing round each accepted seed). Lattice: a
// hexagonal lattice at `lattice_spacing` (the widest circle's radius, at most max_size) where the spacing allows it, the
// rest as Random. Each seed of `seed` gives the same seeds.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "refinement/sizing_field.hpp"
#include "vorocrust/plane.hpp"

namespace vorocrust::interior {

inline constexpr double kPlaneClearance = 1.3;

class PlaneSpacing {
 public:
  // `frame`: where it is asked most, which a coarse grid of cells far from every circle covers.
  PlaneSpacing(const std::vector<PlaneCircle>& circles, const SizingField& sizing, double lipschitz, double largest,
               const Eigen::AlignedBox2d& frame);
  double operator()(const Point2& x) const;
  // Whether x lies inside some circle scaled by kPlaneClearance.
  bool in_clearance(const Point2& x) const;
  double lipschitz() const;

 private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
};

std::vector<Seed> sample_plane(const std::vector<Seed>& boundary, const PlaneSpacing& spacing,
                               const Eigen::AlignedBox2d& frame, InteriorMode mode, double lattice_spacing,
                               std::uint64_t seed);

}  // namespace vorocrust::interior
