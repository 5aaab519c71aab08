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
#include <memory>
#include <vector>

#include "features/strata.hpp"
#include "refinement/boundary_samples.hpp"
#include "refinement/sizing_field.hpp"
#include "vorocrust/balls.hpp"
#include "vorocrust/stats.hpp"
#include "vorocrust/progress.hpp"

namespace vorocrust {

struct RefinementOptions {
  double lipschitz = 0.25;
  double sharp_angle = 0.0;  // radians
  std::uint64_t seed = 0;
  BoundarySampleCounts samples;
  int max_rounds = 200;  // safety net on the phase loop
};

class BallIndex;

// The refinement as a state that outlives one run: sliver elimination (paper 2.4) shrinks balls
// and runs the refinement again, which then resumes from the lowest stratum type it shrank and
// only where cover was lost. Ball indices are stable: balls are added, never removed.
class BallRefinement {
 public:
  BallRefinement(const SurfaceMesh& mesh, const Strata& strata, const SizingField& sizing,
                 const RefinementOptions& options, const ProgressCallback& progress, RefinementStats& stats);
  ~BallRefinement();

  // Refines until C1-C4 hold again (the first call builds the whole union of balls).
  void run();
  std::vector<Ball> balls() const;
  const BallIndex& index() const;
  // Only shrinks (a larger radius is ignored); the next run() restores C1-C4 around the ball.
  void shrink_for_slivers(std::uint32_t ball, double radius);
  // The same, counted apart: to split a skinny surface triangle.
  void shrink_for_skinny_triangle(std::uint32_t ball, double radius);
  // How deep coverage must be, as a share of a radius: 1 - alpha, or 1 - alpha/2 in safe mode.
  double deep_coverage() const;
  // Safe mode (paper 2.4): from now on alpha/2-deep coverage suffices, which bounds how often
  // shrinking for slivers can ask for new balls, so sliver elimination always ends.
  void relax_deep_coverage();

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

// One run of the refinement from scratch.
std::vector<Ball> refine_balls(const SurfaceMesh& mesh, const Strata& strata, const SizingField& sizing,
                               const RefinementOptions& options, const ProgressCallback& progress,
                               RefinementStats& stats);

}  // namespace vorocrust
