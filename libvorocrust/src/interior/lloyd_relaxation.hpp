// Internal: centroidal Voronoi relaxation of the interior seeds (paper 2.5, Figure 5d).
//
// Each iteration computes the cells and moves every interior seed (kind Interior) to its cell's
// centroid; surface and outside seeds stay. A seed whose cell touches a surface seed's cell does
// not move away from the nearest such surface seed (only the rest of its step is taken): drawn
// deeper, it would stretch the thin surface cells it bounds (on cgal_fandisk their mean aspect
// ratio rose from 3.26 to 3.36 in 20 free iterations). A move may not take a seed into a protecting ball or
// a surface seed's ball, where it would cut into the surface facets: such a move is halved, up to
// three times, and otherwise not made; so is one within the sampler's clearance of a ball
// (kBallClearance). Cap seeds stay where they are, as surface seeds do. The centroid lies inside
// the seed's own convex cell, hence in its own region. Returns the largest move of the last
// iteration relative to the mover's radius (0 when no seed moved).
#pragma once

#include <vector>

#include "vorocrust/progress.hpp"
#include "vorocrust/seeds.hpp"

namespace vorocrust {

class BallIndex;

double lloyd_relaxation(std::vector<Seed>& seeds, const BallIndex& protecting_balls, int iterations, int threads,
                        const ProgressCallback& progress);

}  // namespace vorocrust
