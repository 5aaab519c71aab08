// Internal: a point of the input surface together with what the refinement needs to know about
// where it lies — its stratum, the input element (vertex, edge or face) holding it, and the
// stratum's direction there (crease tangent or patch normal, paper 2.3 "Smooth Neighborhoods").
#pragma once

#include "features/strata.hpp"

namespace vorocrust {

struct SurfaceSite {
  Point position;
  Point direction = Point::Zero();  // unit; zero at corners
  StratumType type = StratumType::Patch;
  Index stratum = 0;
  Index element = 0;  // corner: vertex; crease: edge; patch: face
};

// The site of a point on a crease edge or patch face (the point is assumed to lie on it).
SurfaceSite corner_site(const Strata& strata, const SurfaceMesh& mesh, Index corner);
SurfaceSite crease_site(const Strata& strata, Index edge, const Point& position);
SurfaceSite patch_site(const Strata& strata, Index face, const Point& position);

// The relaxed co-smoothness test of paper 2.3, as docs/ball-conditions.md states it: may a ball
// centred at `center` contain the surface point `x`?
class CoSmoothness {
 public:
  // Offsets shorter than `negligible` carry no direction and count as co-smooth.
  CoSmoothness(const Strata& strata, double sharp_angle, double negligible);

  bool operator()(const SurfaceSite& center, const SurfaceSite& x) const;
  // How near to `center` a point of patch face `face` may lie and still fail to be co-smooth with
  // it, given `on_plane`, any point of the face's plane: the points of the face at this distance
  // or beyond all are co-smooth. 0 when every point of the face is; infinity when none need be.
  double non_cosmooth_reach(const SurfaceSite& center, Index face, const Point& on_plane) const;
  // Whether stratum `higher` is incident to stratum `lower` (of lower dimension).
  bool incident(StratumType lower_type, Index lower, StratumType higher_type, Index higher) const;

 private:
  bool position_test(const SurfaceSite& center, const SurfaceSite& x) const;

  const Strata& strata_;
  double cos_theta_;
  double sin_theta_;
  double negligible_;
};

}  // namespace vorocrust
