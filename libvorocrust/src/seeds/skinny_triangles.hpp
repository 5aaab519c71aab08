// Internal: skinny triangles of the surface and the balls to shrink so that the refinement
// samples where they are (paper 2.4; Delaunay refinement's rule of the circumcentre).
//
// The surface is the triangulation of ball centres dual to the seed pairs. Deep coverage (C4)
// keeps centres at least (1 - alpha) r apart and a triangle's circumcentre within (1 - alpha) r
// of some centre, which bounds angles below by 30 degrees where neighbouring radii are equal.
// Where they are not, a larger ball can deeply cover the circumcentre of a triangle of smaller
// neighbours, and nothing is sampled there: the triangle keeps a short edge facing far corners.
// Shrinking the patch balls that deeply cover its circumcentre until they no longer do lets the
// next run of the refinement place a ball near the circumcentre, which splits the triangle.
//
// Only triangles of three patch balls are taken: near creases and corners the protecting balls
// set the spacing, and shrinking patch balls there only adds balls (on the shared CAD models it
// lowered the smallest angle).
#pragma once

#include <cstddef>
#include <vector>

#include "refinement/ball_index.hpp"
#include "seeds/ball_shrinks.hpp"
#include "seeds/seed_pairs.hpp"

namespace vorocrust {

struct SkinnyTriangleShrinks {
  std::size_t skinny = 0;  // triangles of three patch balls with an angle below the bound
  // Patch balls covering their circumcentres deeply, each to just less.
  BallShrinks shrinks;
};

// The triangles of `pairs` (their balls' centres) with an angle below `min_angle_degrees`, and
// the shrinks that uncover their circumcentres: each patch ball of the triangle's patches to
// (1 - 5 %) of the radius within which it would cover the circumcentre `deep_coverage` deep.
// A circumcentre inside a crease or corner ball asks nothing: the protecting ball keeps patch
// samples out there whatever the patch balls do.
SkinnyTriangleShrinks choose_skinny_triangle_shrinks(const BallIndex& balls, const std::vector<SeedPair>& pairs,
                                                     double min_angle_degrees, double deep_coverage);

}  // namespace vorocrust
