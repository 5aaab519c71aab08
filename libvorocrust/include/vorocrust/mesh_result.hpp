// vorocrust/mesh_result.hpp — what a mesh run makes: every stage's result and figures.
//
// Parts of stages the run did not reach stay empty: seeds and surface before Stage::Surface,
// cells before Stage::Cells.
#pragma once

#include "vorocrust/api.hpp"

#include <optional>
#include <vector>

#include "vorocrust/balls.hpp"
#include "vorocrust/cell_quality.hpp"
#include "vorocrust/cells.hpp"
#include "vorocrust/quality.hpp"
#include "vorocrust/regions.hpp"
#include "vorocrust/resolve_self_intersections.hpp"
#include "vorocrust/seeds.hpp"
#include "vorocrust/stats.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

struct VOROCRUST_API MeshResult {
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
  // What cutting the cells to the input did, for MeshOptions::method Clipped.
  std::optional<ClippingStats> clipping;
  // The tetrahedra dual to the clipped cells and their shape, for MeshOptions::method Clipped
  // (measured before welding, which joins Voronoi vertices).
  std::optional<DualTetFigures> dual_tets;
  // What welding short edges did, for MeshOptions::weld above 0.
  std::optional<WeldStats> welding;
  // The cells measured as the paper's section 3 does (aspect ratio, volume, faces, edges).
  std::optional<CellQuality> cell_quality;
};

}  // namespace vorocrust
