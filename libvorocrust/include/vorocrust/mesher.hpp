// vorocrust/mesher.hpp — the whole pipeline, from an input surface to a conforming Voronoi mesh.
//
// Stages (paper sections): features 2.2 -> refinement 2.3 -> seeds 2.4 -> interior 2.5 -> cells.
// Every front end (CLI, Python, MeshLab, FreeCAD) calls generate_mesh() with the same options.
// Runs are reproducible: equal input, options and seed give equal output.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "vorocrust/balls.hpp"
#include "vorocrust/cells.hpp"
#include "vorocrust/progress.hpp"
#include "vorocrust/cell_quality.hpp"
#include "vorocrust/quality.hpp"
#include "vorocrust/regions.hpp"
#include "vorocrust/resolve_self_intersections.hpp"
#include "vorocrust/seeds.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

// How far the pipeline runs: the protecting balls (2.3), the surface seeds and the surface mesh
// (2.4), or the whole Voronoi mesh.
enum class Stage { Balls, Surface, Cells };

// How the volume away from the surface is seeded (paper 2.5, A.5):
// - Random: maximal Poisson-disk sampling with L-Lipschitz radii grown from the surface seeds
//   (dart throwing, then spoke darts), graded from the surface inward;
// - Lattice: a cubic lattice of the local size, giving hex-dominant cells (paper Figure 5f);
// - Cvt: Random, then Lloyd iterations moving interior seeds to their cell centroids while the
//   surface seeds stay where they are (paper Figure 5d).
enum class InteriorMode { Random, Lattice, Cvt };

const char* to_string(InteriorMode mode) noexcept;

// What becomes of faces that cut through each other:
// - Resolve: they are cut along their intersection curves, which become creases, and each new
//   piece of space joins a region of the input (resolve_self_intersections.hpp);
// - Refuse: the front ends stop with the validation's error naming the faces;
// - Keep: meshed as they are, which rarely ends well (the refinement cannot cover a surface
//   that crosses itself).
enum class SelfIntersections { Resolve, Refuse, Keep };

const char* to_string(SelfIntersections mode) noexcept;
// The mode to_string names `name`, if any.
std::optional<SelfIntersections> parse_self_intersections(std::string_view name) noexcept;

struct MeshOptions {
  double lipschitz = 0.25;  // L < 1: how fast ball radii may vary
  // The input approximates a smooth surface (a scan, a coarse tessellation of a curved shape): it
  // is smoothed as one patch (only boundary and non-manifold edges stay fixed), and its features
  // are found afterwards, on the smoothed surface, so the folds of its tessellation are not
  // creases. Unless told otherwise theta# is 60 degrees and smoothing takes 6 rounds of Loop
  // subdivision, the paper's settings for smooth models. On igl_bunny this takes the surface's
  // smallest angle from 0.9 to 23 degrees: the creases the default rules find on a decimated scan
  // are not the shape's and pinch the balls around them.
  bool smooth = false;
  // theta#: an edge whose faces' normals differ by more than this is a sharp crease; it also
  // bounds how far normals may turn between co-smooth points. Unset: 30 degrees, which keeps
  // every crease of the shared CAD models (fandisk, joint, bracket, hinge) while the tessellation
  // rings of curved surfaces (22.5 degrees on sandia_torus) stay smooth; 60 with `smooth`.
  std::optional<double> sharp_angle_degrees;
  double max_size = std::numeric_limits<double>::infinity();  // uniform sizing bound
  std::filesystem::path sizing_file;  // optional: lines "x y z size", interpolated
  // Rounds of adaptive Loop subdivision inside patches (paper 2.2 uses 6), at most: fewer are
  // applied when more would make a feature (checked by detecting features afresh). Unset: 0, as
  // on CAD models it costs more than it gives (the surface grows, sandia_torus 9 216 faces to
  // 189 504, and the refinement with it); 6 with `smooth`.
  std::optional<int> smoothing_iterations;
  // How far smoothing should move the surface from the input at most, as a fraction of the
  // input's bounding-box diagonal: before Loop's rounds, the faces around a vertex that Loop's
  // rules would move farther than this (its limit point, along its normal) are split at their
  // edge midpoints, up to twice, each split halving that move (features/smooth_patches.hpp). A
  // target, not a bound: a vertex that would move more than four times as far still moves more
  // (FeatureCounts::smoothing_largest_offset says how far). Loop's
  // rules shrink a coarse tessellation of a strongly bent shape: directional_bimba (697
  // vertices) ends 1.56 % of its diagonal from its input without these splits, 0.85 to 0.91 %
  // with them (seeds 0 to 4). Three quarters of the paper's 1 %, which leaves the rest to the
  // balls' sampling of the smooth surface; at 0.005, a second round of splits doubles the
  // triangles and the time for 0.7 %. Where the tessellation is fine for its bends (igl_bunny,
  // sandia_torus, sandia_bird) nothing is split. 0: Loop's rules alone, as the paper smooths.
  double smoothing_tolerance = kDefaultSmoothingTolerance;
  static constexpr double kDefaultSmoothingTolerance = 0.0075;
  // Surface triangles of patch balls with an angle below this are split by shrinking the balls
  // that cover their circumcentres deeply (seeds/skinny_triangles.hpp), for at most 10 rounds;
  // 0 splits none. Unset: 0, as on CAD models the worst triangles sit at creases and corners,
  // where this only adds balls; 30 with `smooth`, the paper's figures for smooth models (0.07 %
  // of angles below 30 degrees). On igl_bunny with `smooth` it takes the share below 30 degrees
  // from 0.68 % to 0.003 % and Q min from 0.40 to 0.46, for 28 % more surface triangles. At most
  // 30: deep coverage bounds angles by 30 degrees only, and past it the splits make more skinny
  // triangles than they remove (sandia_bird at 33: 341, then 860 after ten rounds).
  std::optional<double> min_triangle_angle_degrees;

  static constexpr double kSharpAngleDegrees = 30, kSmoothSharpAngleDegrees = 60;
  static constexpr int kSmoothSmoothingIterations = 6;
  static constexpr double kSmoothMinTriangleAngleDegrees = 30, kMaxMinTriangleAngleDegrees = 30;
  // The values in force: the ones set, or the defaults of the mode.
  double sharp_angle() const {
    return sharp_angle_degrees.value_or(smooth ? kSmoothSharpAngleDegrees : kSharpAngleDegrees);
  }
  int smoothing_rounds() const { return smoothing_iterations.value_or(smooth ? kSmoothSmoothingIterations : 0); }
  double min_triangle_angle() const {
    return min_triangle_angle_degrees.value_or(smooth ? kSmoothMinTriangleAngleDegrees : 0);
  }
  // The domain around open sheets (paper Figure 17): {xmin, ymin, zmin, xmax, ymax, zmax}. Its
  // sides join the surface and what is outside every material inside it becomes the material
  // "domain"; an unlabelled sheet then has that material on both sides and splits the cells
  // touching it. Without a box, an input with open edges gets its bounding box grown by a tenth
  // of its diagonal on every side; a closed input gets none.
  std::optional<std::array<double, 6>> box;
  SelfIntersections self_intersections = SelfIntersections::Resolve;
  InteriorMode interior = InteriorMode::Random;
  int cvt_iterations = 20;  // Lloyd iterations of InteriorMode::Cvt
  // Cells whose aspect ratio (smallest enclosing sphere over largest inscribed ball) exceeds this
  // get a seed at their centroid, for at most 2 rounds (interior/cap_seeds.hpp,
  // aspect_split_seeds); a round after which more faces stay highly skew is undone; 0 splits
  // none. 5 by default, above the paper's 4.86 for its smooth model: on igl_bunny with `smooth`
  // the worst cells are spindles from a ball's centre to deep inside, which no interior seed
  // reaches within the balls' clearance. A cell thinner than the balls beside it cannot be split
  // this way and keeps its shape.
  double max_aspect_ratio = kDefaultMaxAspectRatio;
  static constexpr double kDefaultMaxAspectRatio = 5, kLowestMaxAspectRatio = 3;
  Stage stop_after = Stage::Cells;
  std::uint64_t seed = 0;  // random seed; equal seeds give equal meshes
  int threads = 0;         // worker threads generate_mesh runs on, 0 = all hardware threads

  // Throws Error(Usage) naming the first option out of its range.
  void check() const;
};

struct PhaseTiming {
  std::string name;
  double seconds = 0;
};

// What the refinement did (paper Table 1 rows and the counts behind them).
struct RefinementStats {
  std::size_t balls[3] = {0, 0, 0};  // corner, crease, patch balls
  std::size_t darts = 0;
  std::size_t rejected_for_density = 0;
  std::size_t subdivisions = 0;
  std::size_t c1_shrinks = 0;  // balls shrunk for C1/C2 (non-co-smooth contents)
  std::size_t c3_shrinks = 0;  // balls shrunk for the Lipschitz condition
  std::size_t sliver_shrinks = 0;  // balls shrunk to eliminate slivers (paper 2.4)
  std::size_t skinny_triangle_shrinks = 0;  // balls shrunk to split skinny surface triangles
  std::size_t rounds = 0;      // passes of the phase loop, over all runs
  std::size_t boundary_samples = 0;
  bool converged = true;
  double setup_seconds = 0;                  // boundary k-d trees
  double phase_seconds[3] = {0, 0, 0};       // corner protection, edge protection, surface coverage
  double c3_seconds = 0;                     // fixing C3 violations
  double sweep_seconds = 0;                  // final C1/C2 sweep over dense samples
};

// One round of sliver elimination (paper 2.4, Figure 9): the triplets of overlapping balls as
// found, how many had a half-covered seed pair, and the shrinking that followed: for the
// slivers, or, once no pair was half-covered, to split skinny surface triangles.
struct SliverIteration {
  enum class Shrunk { Nothing, ForSlivers, ForSkinnyTriangles };
  Shrunk shrunk = Shrunk::Nothing;  // Nothing: the last iteration
  std::size_t balls = 0;
  std::size_t triplets = 0;      // triplets whose spheres meet in two points
  std::size_t half_covered = 0;  // of them, with exactly one point inside a fourth ball
  std::size_t balls_shrunk = 0;
  double max_shrinkage_ratio = 0;  // Delta: the largest (r - r') / r applied
  // Surface triangles of patch balls with an angle below the bound, counted once no pair is
  // half-covered (0 before, and without a bound).
  std::size_t skinny_triangles = 0;
  double seconds = 0;              // finding the pairs, shrinking and refining again
};

struct SliverStats {
  std::vector<SliverIteration> iterations;  // the last one found no half-covered pair
  // alpha/2-deep coverage accepted after 100 sliver rounds in a row (no split between them)
  bool safe_mode = false;
  // Rounds of shrinking: every iteration but the last, which found nothing to shrink.
  std::size_t rounds() const { return iterations.empty() ? 0 : iterations.size() - 1; }
  std::size_t rounds_for(SliverIteration::Shrunk why) const {
    return static_cast<std::size_t>(
        std::count_if(iterations.begin(), iterations.end(), [&](const SliverIteration& it) { return it.shrunk == why; }));
  }
};

// How the interior was seeded (paper A.5).
struct InteriorStats {
  std::size_t interior_seeds = 0;  // seeds inside a material, away from the surface
  std::size_t outside_seeds = 0;   // seeds outside every material, bounding the boundary cells
  std::size_t cap_seeds = 0;       // seeds on protecting spheres (poles and skew repairs), SeedKind::Cap
  std::size_t split_seeds = 0;     // seeds splitting a cell (about a highly skew face, or too long), SeedKind::Repair
  std::size_t repair_seeds = 0;    // placed to remove highly skew faces after the cells: caps and splits
  int repair_rounds = 0;           // rounds of those repairs (each computing the cells again)
  std::size_t aspect_split_seeds = 0;  // placed at the centroids of cells above MeshOptions::max_aspect_ratio
  int aspect_split_rounds = 0;         // rounds of those kept (each cutting the cells about them again)
  int aspect_split_rounds_undone = 0;  // a round after which more faces stayed highly skew is undone
  std::size_t darts = 0;           // seeds from dart throwing
  std::size_t spokes = 0;          // spokes shot
  std::size_t spoke_seeds = 0;     // seeds placed on spokes
  std::size_t lattice_seeds = 0;   // seeds on the lattice (InteriorMode::Lattice)
  std::size_t lipschitz_shrinks = 0;
  std::size_t rounds = 0;          // spoke passes: one, and one more after each pass that shrank a ball
  int cvt_iterations = 0;
  double cvt_last_move = 0;        // the largest move of the last Lloyd iteration over the seed's radius
};

struct FeatureCounts {
  std::size_t sharp_edges = 0, corners = 0, creases = 0, patches = 0;
  std::size_t faces_after_smoothing = 0;
  int smoothing_iterations = 0;      // rounds applied
  int smoothing_bounding_rounds = 0;  // rounds of midpoint splits before them (MeshOptions::smoothing_tolerance)
  // After those splits, how far Loop's rules move the vertex they move farthest (its limit point
  // along its normal), over the bounding-box diagonal; 0 without a smoothing tolerance.
  double smoothing_largest_offset = 0;
  int smoothing_rounds_refused = 0;   // fewest rounds that made a new feature (0: none did)
  // Fewest rounds refused as they carried the surface through itself: faces crossing, or a shell
  // moved wholly across another (0: none was).
  int smoothing_rounds_crossing = 0;
};

struct MeshResult {
  std::vector<PhaseTiming> timings;
  // The regions of space the input cuts out (label_regions), indexed by label: 0 outside.
  std::vector<RegionSummary> regions;
  // What cutting the faces that cross each other did (all zero faces_cut when none did).
  SelfIntersectionStats self_intersections;
  FeatureCounts features;
  // The surface the balls cover: the input, with the box's sides when it has one, after patch
  // smoothing (paper 2.2), which keeps every sharp feature exactly and moves only vertices
  // inside smooth patches.
  SurfaceMesh smoothed_input;
  std::vector<Ball> balls;
  RefinementStats refinement;
  // From Stage::Surface on: the seeds (surface seeds first, two per seed pair) and the output
  // surface, whose vertices are ball centres and whose faces carry the regions they separate.
  std::vector<Seed> seeds;
  SurfaceMesh surface;
  SliverStats slivers;
  // The surface measured against the input as the paper's section 3 does (angles, triangle
  // quality, two-sided Hausdorff distance, topology).
  std::optional<SurfaceQuality> surface_quality;
  // From Stage::Cells on: seeds holds the interior and outside seeds after the surface seeds,
  // and cells the conforming Voronoi mesh of the material seeds.
  InteriorStats interior;
  VoronoiMesh cells;
  // The cells measured as the paper's section 3 does (aspect ratio, volume, faces, edges).
  std::optional<CellQuality> cell_quality;
};

// The surface the pipeline starts from: `input` in its box (options.box, or the default box of an
// input with open sheets), then cut along its self-intersections when options.self_intersections
// is Resolve (`stats`, when given, says what the cutting did). The balls cover this surface (or
// its smoothing), so `check-balls` checks them against it. Throws Error(InvalidGeometry) for a
// vertex outside the box or faces the cutting cannot separate.
SurfaceMesh prepare_domain(const SurfaceMesh& input, const MeshOptions& options, SelfIntersectionStats* stats = nullptr);

// Runs the pipeline up to options.stop_after. Throws Error: Usage for options out of range,
// Cancelled when progress returns false, InvalidGeometry when the input cannot be meshed.
MeshResult generate_mesh(const SurfaceMesh& input, const MeshOptions& options, const ProgressCallback& progress = {});

}  // namespace vorocrust
