// The cells of a run: the conforming Voronoi mesh of its seeds, repaired where it needs it.
//
// Contract of conforming_cells(seeds, caps, balls, regions, options, phases, stats):
// - Cuts the cell of every material seed ("cells").
// - Faces more skew than options.max_skewness get a repair seed (repair_seeds.hpp) and the cells
//   about the new seeds are cut again ("skew repair"). A repair seed in a thin wedge between
//   crossing surfaces can make a skew face beside the one it removes, so rounds go on while the
//   count falls: two rounds without a fall, a round with no seed to place, or 24 rounds end it.
// - Cells of aspect ratio above options.max_aspect_ratio get a seed at their centroid and the
//   skew faces that makes are repaired, for at most 2 rounds ("aspect splits"). A round after
//   which more faces stay highly skew than before it is undone and ends the splitting: where
//   sheets cross at a small angle, the repair cannot always undo what splits there do, and a
//   cell too long costs a simulation less than a face checkMesh fails.
// - The seeds placed are appended to `seeds` (and to `caps`, the seeds on spheres, which later
//   ones keep clear of); `stats` counts the rounds and seeds. The cells are welded and assembled
//   once, for the seeds as they stand ("assembly").
#pragma once

#include <vector>

#include "core/phases.hpp"
#include "vorocrust/cells.hpp"
#include "vorocrust/seeds.hpp"
#include "vorocrust/stats.hpp"

namespace vorocrust {

class BallIndex;
class RegionLocator;

struct ConformingCellsOptions {
  CellsOptions cells;
  double max_aspect_ratio = 0;  // 0: no splits
  double max_skewness = 4;      // checkMesh's bound of a highly skew face
};

VoronoiMesh conforming_cells(std::vector<Seed>& seeds, std::vector<Seed>& caps, const BallIndex& balls,
                             const RegionLocator& regions, const ConformingCellsOptions& options, Phases& phases,
                             InteriorStats& stats);

}  // namespace vorocrust
