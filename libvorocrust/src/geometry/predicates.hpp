// Internal: exact orientation predicates on double coordinates.
//
// Contract: each predicate returns the sign (+1, 0, -1) of the determinant of its inputs as if it
// were evaluated in exact real arithmetic, never a rounded guess: exactly collinear or coplanar
// inputs give 0, and nearly degenerate ones get their true sign. Inputs must be finite. Exactness
// also needs the exact products not to underflow or overflow, which holds whenever every
// coordinate is 0 or has a magnitude between 1e-60 and 1e60 — far outside any mesh we meet.
//
// Sign conventions:
//   orient2d(a, b, c)    = sign of (b - a) x (c - a): +1 when a, b, c turn counter-clockwise
//                          (c left of the directed line a->b), -1 clockwise, 0 collinear.
//   orient3d(a, b, c, d) = sign of det[b - a; c - a; d - a] = sign of ((b - a) x (c - a)) . (d -
//   a):
//                          +1 when d lies on the side of plane abc that the right-hand normal
//                          (b - a) x (c - a) points to, -1 on the other side, 0 coplanar.
//                          (This is the opposite of the sign Shewchuk's orient3d returns.)
// Both equal, up to a fixed sign, the determinant whose rows are the arguments extended by a 1,
// so swapping any two arguments flips the result.
#pragma once

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::geometry {

int orient2d(double ax, double ay, double bx, double by, double cx, double cy);

int orient3d(const Point& a, const Point& b, const Point& c, const Point& d);

}  // namespace vorocrust::geometry
