// Internal: the point of a segment or triangle nearest to a given point, and the distance to it.
//
// Contract: exact up to rounding for any finite input; degenerate elements are handled as the
// point sets they are (a segment of zero length is its end point, a zero-area triangle the
// nearest of its edges), so no input yields NaN.
#pragma once

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::geometry {

Point closest_on_segment(const Point& p, const Point& a, const Point& b);
Point closest_on_triangle(const Point& p, const Point& a, const Point& b, const Point& c);
double distance_to_segment(const Point& p, const Point& a, const Point& b);
double distance_to_triangle(const Point& p, const Point& a, const Point& b, const Point& c);

}  // namespace vorocrust::geometry
