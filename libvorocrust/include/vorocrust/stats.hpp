// vorocrust/stats.hpp — what each stage of a mesh run did: the counts and times report.json holds.
//
// Plain figures, filled by the stages as they run (the paper's Table 1 rows and Figure 9 among
// them); nothing here computes anything.
#pragma once

#include "vorocrust/api.hpp"

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace vorocrust {

struct VOROCRUST_API PhaseTiming {
  std::string name;
  double seconds = 0;
  // The most bytes the process held resident at once by the phase's end (0 where the system does
  // not say): the phase that raises it is the one that sets a run's peak.
  std::size_t peak_resident_bytes = 0;
};

// What the refinement did (paper Table 1 rows and the counts behind them).
struct VOROCRUST_API RefinementStats {
  std::size_t balls[3] = {0, 0, 0};  // corner, crease, patch balls
  std::size_t darts = 0;
  std::size_t rejected_for_density = 0;
  std::size_t subdivisions = 0;
  // The most pieces of the surface awaiting darts at once, over all passes: the refinement's memory
  // beside its balls (a pool that outgrows the surface's faces many times is refused as one that
  // cannot converge).
  std::size_t largest_pool = 0;
  std::size_t c1_shrinks = 0;  // balls shrunk for C1/C2 (non-co-smooth contents)
  std::size_t c3_shrinks = 0;  // balls shrunk for the Lipschitz condition
  std::size_t sliver_shrinks = 0;  // balls shrunk to eliminate slivers (paper 2.4)
  std::size_t skinny_triangle_shrinks = 0;  // balls shrunk to split skinny surface triangles
  std::size_t rounds = 0;      // passes of the phase loop, over all runs
  std::size_t boundary_samples = 0;
  // Pieces still bare after the deepest subdivision (2^-40 of their element), which the
  // refinement gives up on, and their length on creases and area on patches: 0 in every run
  // measured.
  std::size_t bare_pieces = 0;
  double bare_measure[2] = {0, 0};
  bool converged = true;
  double setup_seconds = 0;                  // boundary k-d trees
  double phase_seconds[3] = {0, 0, 0};       // corner protection, edge protection, surface coverage
  double c3_seconds = 0;                     // fixing C3 violations
  double sweep_seconds = 0;                  // final C1/C2 sweep over dense samples
};

// One round of sliver elimination (paper 2.4, Figure 9): the triplets of overlapping balls as
// found, how many had a half-covered seed pair, and the shrinking that followed: for the
// slivers, or, once no pair was half-covered, to part near-twin seeds or split skinny surface
// triangles.
struct VOROCRUST_API SliverIteration {
  enum class Shrunk { Nothing, ForSlivers, ForSkinnyTriangles, ForNearTwins };
  Shrunk shrunk = Shrunk::Nothing;  // Nothing: the last iteration
  std::size_t balls = 0;
  std::size_t triplets = 0;      // triplets whose spheres meet in two points
  std::size_t half_covered = 0;  // of them, with exactly one point inside a fourth ball
  std::size_t balls_shrunk = 0;
  double max_shrinkage_ratio = 0;  // Delta: the largest (r - r') / r applied
  // Surface triangles of patch balls with an angle below the bound, counted once no pair is
  // half-covered (0 before, and without a bound).
  std::size_t skinny_triangles = 0;
  // Points of two seed pairs nearer than 1e-4 of their radius, counted once no pair is
  // half-covered (seeds/near_twins.hpp).
  std::size_t near_twins = 0;
  double seconds = 0;              // finding the pairs, shrinking and refining again
};

struct VOROCRUST_API SliverStats {
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
struct VOROCRUST_API InteriorStats {
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
  // The memory guard (MeshOptions::max_memory_gb), once the seeds are placed: the bytes resident
  // then, and the run's estimated peak, those plus kCellBytes for each cell to cut (0 where the
  // system does not say what is resident).
  std::size_t resident_bytes_before_cells = 0;
  std::size_t estimated_peak_bytes = 0;
};

// What cutting the cells to the input did (MeshOptions::method Clipped; clipping/clip_cells.hpp).
// What the perturbation of the dual tetrahedra's slivers did (MeshOptions::sliver_angle).
struct VOROCRUST_API SliverPerturbation {
  int rounds = 0;
  std::size_t slivers_before = 0;  // tetrahedra with an angle below the bound, before
  std::size_t slivers_after = 0;   // and in the mesh
  std::size_t moves_tried = 0;
  std::size_t moves_kept = 0;
};

struct VOROCRUST_API ClippingStats {
  std::size_t clipped_cells = 0;   // cells the surface crosses
  std::size_t surface_pieces = 0;  // parts of input triangles in a cell, before those in one plane join
  std::size_t clipped_faces = 0;   // faces between cells that the surface crosses
  std::size_t dropped_faces = 0;   // faces between cells wholly outside the material
  std::size_t holes = 0;           // holes in faces' parts, each cut out by two diagonals
  // Input triangles whose parts in the cells leave some of their area out: a part of the surface
  // nearer an outside seed than every material seed (the outside seeds then move farther, and
  // the final figures have none).
  std::size_t uncovered_triangles = 0;
  SliverPerturbation slivers;
};

// What welding short edges did (MeshOptions::weld; cells/weld_short_edges.hpp).
struct VOROCRUST_API WeldStats {
  double fraction = 0;               // of the local spacing below which an edge is short
  std::size_t short_edges = 0;       // edges found shorter
  std::size_t welded_points = 0;     // points that became part of another
  std::size_t dropped_faces = 0;     // faces left with fewer than three points
  std::size_t kept_edges = 0;        // short edges left, where welding would pinch a face or flatten a cell
  std::size_t non_planar_faces = 0;  // faces off their plane by more than 1e-12 of their diameter
  double max_non_planarity = 0;      // largest distance from a face's plane over its diameter
  double shortest_edge_before = 0;   // over the local spacing
  double shortest_edge_after = 0;
};

// The tetrahedra dual to a clipped mesh (Yan et al. 2011, 5.2: the primal Delaunay tetrahedra
// whose circumcentre lies inside a material) and their shape as Yan et al.'s Table 2 gives it.
struct VOROCRUST_API DualTetFigures {
  std::size_t tets = 0;
  std::size_t degenerate_points = 0;  // Voronoi vertices of five cells or more, without a tetrahedron
  double volume = 0;                  // the tetrahedra's: how much of the materials they fill
  double mean_min_dihedral = 0, min_min_dihedral = 0;  // Q1, degrees
  double max_max_dihedral = 0;                         // Q2, degrees
  double mean_radius_ratio = 0, min_radius_ratio = 0;  // Q3 = 3 r_in / r_circ
  double mean_q4 = 0, min_q4 = 0;                      // Q4 = 12 (9 V^2)^(1/3) / sum of squared edges
};

struct VOROCRUST_API FeatureCounts {
  std::size_t sharp_edges = 0, corners = 0, creases = 0, patches = 0;
  std::size_t faces_after_smoothing = 0;
  int smoothing_iterations = 0;      // rounds applied
  int smoothing_bounding_rounds = 0;  // rounds of midpoint splits before them (MeshOptions::smoothing_tolerance)
  // After those splits, how far Loop's rules move the vertex they move farthest (its limit point
  // along its normal), over the bounding-box diagonal; 0 without a smoothing tolerance.
  double smoothing_largest_offset = 0;
  // Faces the smoothing folded over all their neighbours, unfolded (io/unfold_faces.hpp).
  std::size_t smoothing_faces_unfolded = 0;
  int smoothing_rounds_refused = 0;   // fewest rounds that made a new feature (0: none did)
  // Fewest rounds refused as they carried the surface through itself: faces crossing, or a shell
  // moved wholly across another (0: none was).
  int smoothing_rounds_crossing = 0;
};

}  // namespace vorocrust
