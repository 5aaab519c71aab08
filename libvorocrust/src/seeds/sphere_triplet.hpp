// Internal: where the bounding spheres of three balls meet (paper 2.4: the seed pair of a
// triplet).
#pragma once

#include <array>
#include <optional>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

// The two points common to the spheres |x - c_k| = r_k, when the spheres meet in two distinct
// points. points[0] lies on the side the triangle (c0, c1, c2) faces (its right-hand normal),
// points[1] is its mirror image across the triangle's plane. Nothing when the spheres miss one
// another or the centres are (nearly) collinear.
std::optional<std::array<Point, 2>> sphere_triplet_points(const Point& c0, double r0, const Point& c1, double r1,
                                                           const Point& c2, double r2);

}  // namespace vorocrust
