// check_balls/ball_sites.hpp — on which of the checker's strata each ball centre lies.
//
// Contract: locate_balls() ignores the refinement's stratum index and matches by geometry. A ball
// of type T takes the stratum of the nearest element of type T (corner; sharp edge -> its crease;
// face -> its patch) and, as directions, those of every element of that stratum at the nearest
// distance (+ tolerance): a centre on a crease vertex gets both edges' directions.
// It also reports protection violations of the centres: the lowest-dimensional stratum a centre
// lies on (within `tolerance`) must be of the ball's type, so a corner ball sits on a corner, a
// crease ball on a crease but not on a corner, a patch ball on a face but not on a sharp edge.
// Every corner must carry a corner ball (centre within `tolerance`).
#pragma once

#include <vector>

#include "check_balls/co_smooth.hpp"
#include "check_balls/surface_locator.hpp"
#include "check_balls/violation_log.hpp"

namespace vorocrust::checker {

struct BallSite {
  StratumRef stratum;
  std::vector<Point> directions;
};

std::vector<BallSite> locate_balls(const SurfaceMesh& mesh, const Strata& strata, const SurfaceLocator& locator,
                                   const std::vector<CheckedBall>& balls, double tolerance, ViolationLog& log);

void check_corner_balls(const SurfaceMesh& mesh, const Strata& strata, const std::vector<CheckedBall>& balls,
                        double tolerance, ViolationLog& log);

}  // namespace vorocrust::checker
