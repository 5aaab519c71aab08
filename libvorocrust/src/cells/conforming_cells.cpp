#include "cells/conforming_cells.hpp"

#include <algorithm>
#include <optional>

#include "cells/growing_cells.hpp"
#include "core/memory.hpp"
#include "cells/repair_seeds.hpp"

namespace vorocrust {

namespace {

constexpr int kRepairRounds = 24;
constexpr int kSplitRounds = 2;

class RepairedCells {
 public:
  RepairedCells(std::vector<Seed>& seeds, std::vector<Seed>& caps, const BallIndex& balls, const RegionLocator& regions,
                const ConformingCellsOptions& options, Phases& phases, InteriorStats& stats)
      : seeds_(seeds), caps_(caps), balls_(balls), regions_(regions), options_(options), phases_(phases), stats_(stats) {
    skew_ = phases_("cells", [&] {
      cells_.emplace(seeds_, options_.cells);
      return cells_->skew_faces(options_.max_skewness);
    });
  }

  void repair_skew_faces() {
    std::size_t fewest_skew = skew_.size();
    for (int round = 0, stalled = 0; round < kRepairRounds && stalled < 2 && fewest_skew > 0; ++round) {
      const std::vector<Seed> repairs =
          phases_("skew repair", [&] { return skew_repair_seeds(skew_, seeds_, balls_, regions_, caps_); });
      if (repairs.empty()) break;
      ++stats_.repair_rounds;
      stats_.repair_seeds += repairs.size();
      skew_ = phases_("skew repair", [&] { return add_seeds(repairs); });
      stalled = skew_.size() < fewest_skew ? 0 : stalled + 1;
      fewest_skew = std::min(fewest_skew, skew_.size());
    }
  }

  void split_long_cells() {
    for (int round = 0; round < kSplitRounds && options_.max_aspect_ratio > 0; ++round) {
      const std::vector<Seed> splits = phases_("aspect splits", [&] {
        return aspect_split_seeds(cells_->long_cells(options_.max_aspect_ratio), seeds_, balls_, regions_, caps_);
      });
      if (splits.empty()) break;
      const std::size_t seeds_before = seeds_.size(), caps_before = caps_.size(), skew_before = skew_.size();
      const InteriorStats stats_before = stats_;
      ++stats_.aspect_split_rounds;
      stats_.aspect_split_seeds += splits.size();
      skew_ = phases_("aspect splits", [&] { return add_seeds(splits); });
      repair_skew_faces();
      if (skew_.size() > skew_before) {
        seeds_.resize(seeds_before);
        caps_.resize(caps_before);
        stats_ = stats_before;
        ++stats_.aspect_split_rounds_undone;
        // GrowingCells only grows: the cells of the seeds as they were, cut afresh (their skew
        // faces, those before the round, are not needed again).
        phases_("aspect splits", [&] { cells_.emplace(seeds_, options_.cells); });
        return;
      }
    }
  }

  VoronoiMesh assemble() {
    return phases_("assembly", [&] {
      VoronoiMesh mesh = std::move(*cells_).mesh();
      // The cells as cut, their welding and their faces, freed on every worker's heap, go back to
      // the system: they are several times the mesh.
      cells_.reset();
      release_free_memory();
      return mesh;
    });
  }

 private:
  std::vector<cells::CutFace> add_seeds(const std::vector<Seed>& added) {
    caps_.insert(caps_.end(), added.begin(), added.end());
    seeds_.insert(seeds_.end(), added.begin(), added.end());
    cells_->add_seeds(seeds_);
    return cells_->skew_faces(options_.max_skewness);
  }

  std::vector<Seed>& seeds_;
  std::vector<Seed>& caps_;
  const BallIndex& balls_;
  const RegionLocator& regions_;
  const ConformingCellsOptions& options_;
  Phases& phases_;
  InteriorStats& stats_;
  std::optional<cells::GrowingCells> cells_;
  std::vector<cells::CutFace> skew_;
};

}  // namespace

VoronoiMesh conforming_cells(std::vector<Seed>& seeds, std::vector<Seed>& caps, const BallIndex& balls,
                             const RegionLocator& regions, const ConformingCellsOptions& options, Phases& phases,
                             InteriorStats& stats) {
  RepairedCells cells(seeds, caps, balls, regions, options, phases, stats);
  cells.repair_skew_faces();
  cells.split_long_cells();
  return cells.assemble();
}

}  // namespace vorocrust
