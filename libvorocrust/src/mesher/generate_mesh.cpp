#include <tbb/task_arena.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>

#include "cells/growing_cells.hpp"
#include "core/surface_measures.hpp"
#include "features/smooth_patches.hpp"
#include "features/strata.hpp"
#include "geometry/self_intersections.hpp"
#include "interior/cap_seeds.hpp"
#include "interior/lloyd_relaxation.hpp"
#include "io/enclose_in_box.hpp"
#include "interior/sample_interior.hpp"
#include "refinement/refine_balls.hpp"
#include "regions/region_labels_hold.hpp"
#include "seeds/eliminate_slivers.hpp"
#include "seeds/locate_regions.hpp"
#include "seeds/surface_seeds.hpp"
#include "refinement/sizing_field.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/face_skewness.hpp"
#include "vorocrust/mesher.hpp"
#include "vorocrust/regions.hpp"

namespace vorocrust {

void MeshOptions::check() const {
  if (!(lipschitz > 0 && lipschitz < 1)) {
    throw Error(Error::Kind::Usage, "--lipschitz must lie strictly between 0 and 1, got " + std::to_string(lipschitz));
  }
  if (!(sharp_angle() > 0 && sharp_angle() < 90)) {
    throw Error(Error::Kind::Usage,
                "--sharp-angle must lie strictly between 0 and 90 degrees, got " + std::to_string(sharp_angle()));
  }
  if (!(max_size > 0)) throw Error(Error::Kind::Usage, "--max-size must be positive, got " + std::to_string(max_size));
  if (threads < 0) throw Error(Error::Kind::Usage, "--threads must be 0 (all) or positive");
  if (smoothing_rounds() < 0) throw Error(Error::Kind::Usage, "--smoothing-iterations must be 0 or positive");
  if (!(smoothing_tolerance >= 0 && std::isfinite(smoothing_tolerance))) {
    throw Error(Error::Kind::Usage,
                "--smoothing-tolerance must be 0 (none) or positive, got " + std::to_string(smoothing_tolerance));
  }
  if (cvt_iterations < 0) throw Error(Error::Kind::Usage, "--cvt-iterations must be 0 or positive");
  if (!(max_aspect_ratio == 0 || (max_aspect_ratio >= kLowestMaxAspectRatio && std::isfinite(max_aspect_ratio)))) {
    throw Error(Error::Kind::Usage, "--max-aspect-ratio must be 0 (no splits) or at least " +
                                        std::to_string(static_cast<int>(kLowestMaxAspectRatio)) + ", got " +
                                        std::to_string(max_aspect_ratio));
  }
  if (!(min_triangle_angle() >= 0 && min_triangle_angle() <= kMaxMinTriangleAngleDegrees)) {
    throw Error(Error::Kind::Usage, "--min-triangle-angle must lie between 0 and " +
                                        std::to_string(static_cast<int>(kMaxMinTriangleAngleDegrees)) +
                                        " degrees, got " + std::to_string(min_triangle_angle()));
  }
}

const char* to_string(SelfIntersections mode) noexcept {
  switch (mode) {
    case SelfIntersections::Resolve: return "resolve";
    case SelfIntersections::Refuse: return "refuse";
    case SelfIntersections::Keep: return "keep";
  }
  return "?";
}

std::optional<SelfIntersections> parse_self_intersections(std::string_view name) noexcept {
  for (SelfIntersections mode : {SelfIntersections::Resolve, SelfIntersections::Refuse, SelfIntersections::Keep}) {
    if (name == to_string(mode)) return mode;
  }
  return std::nullopt;
}

const char* to_string(InteriorMode mode) noexcept {
  switch (mode) {
    case InteriorMode::Random: return "random";
    case InteriorMode::Lattice: return "lattice";
    case InteriorMode::Cvt: return "cvt";
  }
  return "?";
}

namespace {

class PhaseClock {
 public:
  explicit PhaseClock(std::vector<PhaseTiming>& timings) : timings_(timings) {}
  template <class Work>
  auto operator()(const char* name, Work&& work) {
    const auto start = std::chrono::steady_clock::now();
    auto result = work();
    timings_.push_back({name, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
    return result;
  }

 private:
  std::vector<PhaseTiming>& timings_;
};

MeshResult run_pipeline(const SurfaceMesh& model, const MeshOptions& options, const ProgressCallback& progress);

}  // namespace

SurfaceMesh prepare_domain(const SurfaceMesh& model, const MeshOptions& options, SelfIntersectionStats* stats) {
  SurfaceMesh input = model;
  if (options.box) {
    const auto& b = *options.box;
    input = enclose_in_box(model, geometry::Box{Point(b[0], b[1], b[2]), Point(b[3], b[4], b[5])});
  } else if (needs_box(model) && !holds_its_box(model)) {
    input = enclose_in_box(model, default_box(model));
  }
  // Faces crossing each other cut along their intersection curves, the pieces of space between
  // them joined to the input's regions.
  if (options.self_intersections == SelfIntersections::Resolve) input = resolve_self_intersections(input, stats);
  return input;
}

MeshResult generate_mesh(const SurfaceMesh& model, const MeshOptions& options, const ProgressCallback& progress) {
  options.check();
  // Every parallel stage runs in this arena: a program that asks for n threads gets at most n,
  // with or without a ThreadLimit of its own.
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  return arena.execute([&] { return run_pipeline(model, options, progress); });
}

namespace {

MeshResult run_pipeline(const SurfaceMesh& model, const MeshOptions& options, const ProgressCallback& progress) {
  MeshResult result;
  PhaseClock clock(result.timings);
  // The domain: the model in its box, its self-intersections resolved.
  const auto prepare = [&] { return prepare_domain(model, options, &result.self_intersections); };
  SurfaceMesh input;
  if (options.self_intersections == SelfIntersections::Resolve) {
    if (progress && !progress({"self-intersections", -1})) throw Error(Error::Kind::Cancelled, "cancelled");
    input = clock("self-intersections", prepare);
  } else {
    input = prepare();
  }
  // The regions of space the surface cuts out, each side of each face labelled.
  result.regions = clock("regions", [&] { return label_regions(input); });
  const double sharp_angle = options.sharp_angle() * std::numbers::pi / 180;
  const FeatureDetection detection =
      options.smooth ? FeatureDetection::BoundaryOnly : FeatureDetection::SharpAndBoundary;
  if (progress && !progress({"features", -1})) throw Error(Error::Kind::Cancelled, "cancelled");

  // Features (paper 2.2). A smooth surface is smoothed before its features are found: what its
  // tessellation bends is then gone, and a fold that still bends past theta# is a crease after
  // all (without one, balls either side of it are not co-smooth and shrink without end). A box's
  // sides are no part of the smooth surface: their edges stay creases.
  Strata strata = clock("features", [&] { return detect_strata(input, sharp_angle, detection, box_faces(input)); });

  // Patch smoothing (paper 2.2): flatten the patches so nearby normals agree, features untouched.
  result.smoothed_input = input;
  if (options.smoothing_rounds() > 0) {
    if (progress && !progress({"smoothing", -1})) throw Error(Error::Kind::Cancelled, "cancelled");
    clock("smoothing", [&] {
      // Smoothing must flatten patches, not make features: when the smoothed surface, detected
      // afresh, has sharp edges or corners the carried-through features lack (a cone point
      // appears beside a corner on cgal_fandisk), the run takes one round fewer, down to none.
      // A smooth surface's features before smoothing are its topology's, which subdivision
      // keeps: detected afresh they are the carried ones, so they are not detected again.
      // Nor may smoothing carry a sheet through a nearby one, as Loop's rules pull a coarse
      // convex sheet inward (on openmeeg_HeadNNa1 one round does): the refinement cannot meet
      // the ball conditions where a surface crosses itself (it gave up on that one), so such a
      // round count is refused too, unless the input already crossed itself (--self-intersections
      // keep). Nor may it carry a shell wholly across another, which leaves nothing crossing but
      // the regions' labels on the wrong sides (the cells then find a material no seed encloses).
      // A refused smoothing that stopped early would come again for every round count down to
      // the rounds it applied, so the next try takes one round fewer than those.
      std::optional<bool> input_crosses_itself;
      const double diagonal = bounding_box_diagonal(input);
      for (int rounds = options.smoothing_rounds(); rounds > 0;) {
        SmoothingOptions smoothing;
        smoothing.max_iterations = rounds;
        smoothing.max_deviation = options.smoothing_tolerance * diagonal;
        SmoothedSurface smoothed = smooth_patches(input, strata, smoothing);
        if (smoothed.iterations == 0) break;
        rounds = smoothed.iterations - 1;  // the next try, if this one is refused
        // A smooth surface's features are found afresh below, so only the others are carried.
        std::optional<Strata> carried;
        if (!options.smooth) {
          carried = strata_after_smoothing(smoothed);
          const Strata fresh = detect_strata(smoothed.mesh, sharp_angle);
          if (fresh.sharp_edge != carried->sharp_edge || fresh.corners != carried->corners) {
            result.features.smoothing_rounds_refused = smoothed.iterations;
            continue;
          }
        }
        if (!geometry::find_self_intersections(smoothed.mesh).empty()) {
          if (!input_crosses_itself) input_crosses_itself = !geometry::find_self_intersections(input).empty();
          if (!*input_crosses_itself) {
            result.features.smoothing_rounds_crossing = smoothed.iterations;
            continue;
          }
        }
        if (!region_labels_hold(smoothed.mesh)) {
          result.features.smoothing_rounds_crossing = smoothed.iterations;
          continue;
        }
        result.features.smoothing_iterations = smoothed.iterations;
        result.features.smoothing_bounding_rounds = smoothed.bounding_rounds;
        result.features.smoothing_largest_offset = diagonal > 0 ? smoothed.largest_limit_offset / diagonal : 0;
        if (carried) strata = std::move(*carried);
        result.smoothed_input = std::move(smoothed.mesh);
        break;
      }
      return 0;
    });
  }
  if (options.smooth) {
    strata = clock("features", [&] { return detect_strata(result.smoothed_input, sharp_angle); });
  }
  for (bool sharp : strata.sharp_edge) result.features.sharp_edges += sharp;
  result.features.corners = strata.corners.size();
  result.features.creases = strata.creases.size();
  result.features.patches = strata.num_patches;
  result.features.faces_after_smoothing = result.smoothed_input.num_faces();
  const SurfaceMesh& surface = result.smoothed_input;

  // Refinement (paper 2.3).
  const SizingField sizing = options.sizing_file.empty() ? SizingField(options.max_size)
                                                         : SizingField(options.max_size, options.sizing_file);
  RefinementOptions refinement_options;
  refinement_options.lipschitz = options.lipschitz;
  refinement_options.sharp_angle = sharp_angle;
  refinement_options.seed = options.seed;
  BallRefinement refinement(surface, strata, sizing, refinement_options, progress, result.refinement);
  clock("refinement", [&] {
    refinement.run();
    return 0;
  });
  if (options.stop_after == Stage::Balls) {
    result.balls = refinement.balls();
    return result;
  }

  // Surface seeds and sliver elimination (paper 2.4).
  const SeedPairs pairs = clock("slivers", [&] {
    SliverOptions sliver_options;
    sliver_options.min_triangle_angle_degrees = options.min_triangle_angle();
    return eliminate_slivers(refinement, sliver_options, progress, result.slivers);
  });
  result.balls = refinement.balls();
  const RegionLocator regions(surface);
  SurfaceSeeds seeds = clock("surface seeds", [&] {
    return surface_seeds(refinement.index(), pairs.uncovered, regions);
  });
  result.seeds = std::move(seeds.seeds);
  result.surface = std::move(seeds.surface);
  if (progress && !progress({"surface quality", -1})) throw Error(Error::Kind::Cancelled, "cancelled");
  result.surface_quality = clock("surface quality", [&] { return measure_surface_quality(input, result.surface); });
  if (options.stop_after == Stage::Surface) return result;

  // Interior seeds (paper 2.5, A.5).
  InteriorOptions interior_options;
  interior_options.mode = options.interior;
  interior_options.lipschitz = options.lipschitz;
  interior_options.seed = options.seed;
  geometry::Box domain;
  for (const Point& p : input.vertices) domain.include(p);
  std::vector<Seed> caps = clock("cap seeds", [&] { return pole_seeds(result.seeds, refinement.index(), regions); });
  std::vector<Seed> interior = clock("interior seeds", [&] {
    return sample_interior(result.seeds, caps, refinement.index(), sizing, domain, interior_options, progress,
                           result.interior);
  });
  result.seeds.insert(result.seeds.end(), interior.begin(), interior.end());
  if (options.interior == InteriorMode::Cvt && options.cvt_iterations > 0) {
    result.interior.cvt_iterations = options.cvt_iterations;
    result.interior.cvt_last_move = clock("cvt", [&] {
      return lloyd_relaxation(result.seeds, refinement.index(), options.cvt_iterations, options.threads, progress);
    });
  }

  // Cells.
  if (progress && !progress({"cells", -1})) throw Error(Error::Kind::Cancelled, "cancelled");
  CellsOptions cells_options;
  cells_options.threads = options.threads;
  std::optional<cells::GrowingCells> cells;
  std::vector<cells::CutFace> skew = clock("cells", [&] {
    cells.emplace(result.seeds, cells_options);
    return cells->skew_faces(kHighSkewness);
  });
  // Faces still highly skew get a seed on a sphere, at the face or in a cell that it splits, and
  // the cells about the new seeds are cut again (interior/cap_seeds.hpp). A repair seed in a thin
  // wedge between crossing surfaces can make a skew face beside the one it removes, so rounds go
  // on while the count falls: two rounds without a fall, or a round with no seed to place, end it.
  const auto add_seeds = [&](const std::vector<Seed>& added) {
    caps.insert(caps.end(), added.begin(), added.end());
    result.seeds.insert(result.seeds.end(), added.begin(), added.end());
    cells->add_seeds(result.seeds);
    return cells->skew_faces(kHighSkewness);
  };
  const auto repair_skew_faces = [&] {
    constexpr int kRepairRounds = 24;
    std::size_t fewest_skew = skew.size();
    for (int round = 0, stalled = 0; round < kRepairRounds && stalled < 2 && fewest_skew > 0; ++round) {
      if (progress && !progress({"skew repair", -1})) throw Error(Error::Kind::Cancelled, "cancelled");
      const std::vector<Seed> repairs = clock("skew repair", [&] {
        return skew_repair_seeds(skew, result.seeds, refinement.index(), regions, caps);
      });
      if (repairs.empty()) break;
      ++result.interior.repair_rounds;
      result.interior.repair_seeds += repairs.size();
      skew = clock("skew repair", [&] { return add_seeds(repairs); });
      stalled = skew.size() < fewest_skew ? 0 : stalled + 1;
      fewest_skew = std::min(fewest_skew, skew.size());
    }
  };
  repair_skew_faces();
  // Cells of too large an aspect ratio split at their centroids, and the skew faces that makes
  // repaired, a few times. A round after which more faces stay highly skew than before it is
  // undone, and ends the splitting: where sheets cross at a small angle, the repair cannot always
  // undo what splits there do (openmeeg_HeadNNa1: two faces of skewness 14.4), and a cell too
  // long costs a simulation less than a face checkMesh fails.
  constexpr int kSplitRounds = 2;
  for (int round = 0; round < kSplitRounds && options.max_aspect_ratio > 0; ++round) {
    if (progress && !progress({"aspect splits", -1})) throw Error(Error::Kind::Cancelled, "cancelled");
    const std::vector<Seed> splits = clock("aspect splits", [&] {
      return aspect_split_seeds(cells->long_cells(options.max_aspect_ratio), result.seeds, refinement.index(),
                                regions, caps);
    });
    if (splits.empty()) break;
    const std::size_t seeds_before = result.seeds.size(), caps_before = caps.size(), skew_before = skew.size();
    const InteriorStats stats_before = result.interior;
    ++result.interior.aspect_split_rounds;
    result.interior.aspect_split_seeds += splits.size();
    skew = clock("aspect splits", [&] { return add_seeds(splits); });
    repair_skew_faces();
    if (skew.size() > skew_before) {
      result.seeds.resize(seeds_before);
      caps.resize(caps_before);
      result.interior = stats_before;
      ++result.interior.aspect_split_rounds_undone;
      // GrowingCells only grows: the cells of the seeds as they were, cut afresh (their skew
      // faces, those before the round, are not needed again).
      clock("aspect splits", [&] {
        cells.emplace(result.seeds, cells_options);
        return 0;
      });
      break;
    }
  }
  // The cells welded and assembled once, for the seeds as they stand.
  if (progress && !progress({"assembly", -1})) throw Error(Error::Kind::Cancelled, "cancelled");
  result.cells = clock("assembly", [&] { return std::move(*cells).mesh(); });
  for (const Seed& s : result.seeds) {
    if (s.kind == SeedKind::Outside) ++result.interior.outside_seeds;
    if (s.kind == SeedKind::Interior) ++result.interior.interior_seeds;
    if (s.kind == SeedKind::Cap) ++result.interior.cap_seeds;
    if (s.kind == SeedKind::Repair) ++result.interior.split_seeds;
  }
  result.cells.region_names = result.surface.region_names;
  if (progress && !progress({"cell quality", -1})) throw Error(Error::Kind::Cancelled, "cancelled");
  CellQualityOptions quality_options;
  quality_options.threads = options.threads;
  result.cell_quality = clock("cell quality", [&] { return measure_cell_quality(result.cells, quality_options); });
  return result;
}

}  // namespace

}  // namespace vorocrust
