// Internal: the shape figures of one triangle — its corner angles and its quality — as
// vorocrust/quality.hpp defines them.
#pragma once

#include <array>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::geometry {

struct TriangleShape {
  std::array<double, 3> angles_degrees{};  // at the corners a, b, c
  // Strictly above 90 degrees, by the sign of the dot product of the corner's edges: a right
  // angle made of exactly perpendicular edges is never counted as obtuse by rounding.
  std::array<bool, 3> obtuse{};
  double quality = 0;  // 6 S / (sqrt(3) h p); 0 for zero area
};

TriangleShape triangle_shape(const Point& a, const Point& b, const Point& c);

}  // namespace vorocrust::geometry
