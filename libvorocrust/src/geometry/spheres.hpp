// The two spheres of a cell's aspect ratio (paper section 3, footnote 3): the smallest sphere
// enclosing a point set and the largest ball inside an intersection of half-spaces.
#pragma once

#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::geometry {

struct Sphere {
  Point centre = Point::Zero();
  double radius = 0;
};

// The smallest sphere enclosing `points` (at least one): Welzl's algorithm, move-to-front, over
// the points in an order shuffled from a fixed seed. A point that is nearly in the affine hull of
// the sphere's support already (four coplanar points on a circle, common at the vertices of
// lattice cells) is not made support, and the radius is the distance to the farthest point in
// the end, so the sphere always encloses. Tolerances are relative to the points' extent.
Sphere smallest_enclosing_sphere(std::vector<Point> points);

// A half-space normal . x <= offset, normal of unit length.
struct Plane {
  Point normal = Point::Zero();
  double offset = 0;
};

// The largest ball inside every plane and inside the ball of radius `extent` about `inside`, a
// point inside the planes (its role: the scale and centre of the tolerances; the extent only
// matters for unbounded half-space sets). The linear program of maximising r with
// normal . c + r <= offset for every plane, solved by Seidel's algorithm (small_lp.hpp) over
// the planes nearest `inside` first; the radius is then the distance from the centre to its
// nearest plane, so the ball always fits.
// Radius 0 when the planes leave no interior.
Sphere largest_inscribed_ball(const std::vector<Plane>& planes, const Point& inside, double extent);

}  // namespace vorocrust::geometry
