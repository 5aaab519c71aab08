#include "refinement/surface_site.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vorocrust {

SurfaceSite corner_site(const Strata& strata, const SurfaceMesh& mesh, Index corner) {
  return {mesh.vertices[strata.corners[corner]], Point::Zero(), StratumType::Corner, corner, strata.corners[corner]};
}

SurfaceSite crease_site(const Strata& strata, Index edge, const Point& position) {
  return {position, strata.edge_tangent[edge], StratumType::Crease, static_cast<Index>(strata.edge_crease[edge]), edge};
}

SurfaceSite patch_site(const Strata& strata, Index face, const Point& position) {
  return {position, strata.face_normals[face], StratumType::Patch, strata.face_patch[face], face};
}

CoSmoothness::CoSmoothness(const Strata& strata, double sharp_angle, double negligible)
    : strata_(strata), cos_theta_(std::cos(sharp_angle)), sin_theta_(std::sin(sharp_angle)), negligible_(negligible) {}

bool CoSmoothness::incident(StratumType lower_type, Index lower, StratumType higher_type, Index higher) const {
  const auto contains = [](const std::vector<Index>& sorted, Index value) {
    return std::binary_search(sorted.begin(), sorted.end(), value);
  };
  if (lower_type == StratumType::Corner && higher_type == StratumType::Crease) {
    return contains(strata_.corner_creases[lower], higher);
  }
  if (lower_type == StratumType::Corner && higher_type == StratumType::Patch) {
    return contains(strata_.corner_patches[lower], higher);
  }
  if (lower_type == StratumType::Crease && higher_type == StratumType::Patch) {
    return contains(strata_.crease_patches[lower], higher);
  }
  return false;
}

// On a crease, x - center must run along the crease; on a patch, lie near its tangent plane.
bool CoSmoothness::position_test(const SurfaceSite& center, const SurfaceSite& x) const {
  const Point d = x.position - center.position;
  const double length = d.norm();
  if (length <= negligible_) return true;
  const double c = std::abs(x.direction.dot(d)) / length;
  return x.type == StratumType::Crease ? c >= cos_theta_ : c <= sin_theta_;
}

bool CoSmoothness::operator()(const SurfaceSite& center, const SurfaceSite& x) const {
  if ((x.position - center.position).norm() <= negligible_) return true;
  if (x.type == center.type) {
    // Two points of one straight edge or one flat face are joined by a path inside it.
    if (x.element == center.element && x.type != StratumType::Corner) return true;
    if (x.stratum != center.stratum || x.type == StratumType::Corner) return false;
    return center.direction.dot(x.direction) >= cos_theta_ && position_test(center, x);
  }
  if (x.type < center.type) return false;
  return incident(center.type, center.stratum, x.type, x.stratum) && position_test(center, x);
}

// The test above for a point x of the face, folded over the whole face: strata and directions are
// the face's own, and the offset d = x - center has the same component along the face's normal for
// every x of its plane, so the position test |n . d| <= sin(theta) |d| fails only nearer than
// |n . d| / sin(theta). The margin covers rounding: samples lie on the plane up to it.
double CoSmoothness::non_cosmooth_reach(const SurfaceSite& center, Index face, const Point& on_plane) const {
  constexpr double kAnywhere = std::numeric_limits<double>::infinity();
  const Index patch = strata_.face_patch[face];
  const Point& normal = strata_.face_normals[face];
  if (center.type == StratumType::Patch) {
    if (face == center.element) return 0;
    if (patch != center.stratum || center.direction.dot(normal) < cos_theta_) return kAnywhere;
  } else if (!incident(center.type, center.stratum, StratumType::Patch, patch)) {
    return kAnywhere;
  }
  const double margin = 1e-9 * (center.position.norm() + on_plane.norm());
  return (std::abs(normal.dot(on_plane - center.position)) + margin) / sin_theta_;
}

}  // namespace vorocrust
