// Ball refinement (paper section 2.3): a union of balls that protects the sharp features and
// covers the surface while meeting C1-C4 (docs/ball-conditions.md).
//
// Recursive maximal Poisson-disk sampling: corner balls first, then crease balls, then patch
// balls; whenever a phase shrinks a ball of an earlier phase, refinement goes back to that
// phase for the region the ball no longer covers. Each phase ends by enforcing C3 on its balls,
// and a final sweep over dense samples of the input shrinks any ball that still reaches a point
// it must not contain. Deterministic for a given seed.
#pragma once

#include <cstdint>
#include <vector>

#include "features/strata.hpp"
#include "refinement/boundary_samples.hpp"
#include "refinement/sizing_field.hpp"
#include "vorocrust/balls.hpp"
#include "vorocrust/mesher.hpp"
#include "vorocrust/progress.hpp"

namespace vorocrust {

struct RefinementOptions {
  double lipschitz = 0.25;
  double sharp_angle = 0.0;  // radians
  std::uint64_t seed = 0;
  BoundarySampleCounts samples;
  int max_rounds = 200;  // safety net on the phase loop
};

std::vector<Ball> refine_balls(const SurfaceMesh& mesh, const Strata& strata, const SizingField& sizing,
                               const RefinementOptions& options, const ProgressCallback& progress,
                               RefinementStats& stats);

}  // namespace vorocrust
