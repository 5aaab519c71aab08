#include "features/surface_features.hpp"

#include <optional>

#include "core/surface_measures.hpp"
#include "io/enclose_in_box.hpp"
#include "io/unfold_faces.hpp"
#include "features/smooth_patches.hpp"
#include "geometry/self_intersections.hpp"
#include "regions/region_labels_hold.hpp"

namespace vorocrust {

namespace {

// The vertices smoothing keeps where they are: those of the sharp edges and corners it carried.
std::vector<bool> fixed_vertices(const SmoothedSurface& smoothed) {
  std::vector<bool> fixed(smoothed.mesh.num_vertices(), false);
  for (const auto& edge : smoothed.sharp_edges) fixed[edge[0]] = fixed[edge[1]] = true;
  for (Index v : smoothed.corners) fixed[v] = true;
  return fixed;
}

// Smoothing must flatten patches, not make features: when the smoothed surface, detected afresh,
// has sharp edges or corners the carried-through features lack (a cone point appears beside a
// corner on cgal_fandisk), the run takes one round fewer, down to none. A smooth surface's
// features before smoothing are its topology's, which subdivision keeps: detected afresh they are
// the carried ones, so they are not detected again. Nor may smoothing carry a sheet through a
// nearby one, as Loop's rules pull a coarse convex sheet inward (on openmeeg_HeadNNa1 one round
// does): the refinement cannot meet the ball conditions where a surface crosses itself, so such a
// round count is refused too, unless the input already crossed itself (self_intersections keep).
// Nor may it carry a shell wholly across another, which leaves nothing crossing but the regions'
// labels on the wrong sides (the cells then find a material no seed encloses). A refused smoothing
// that stopped early would come again for every round count down to the rounds it applied, so the
// next try takes one round fewer than those.
void smooth_within_rules(const SurfaceMesh& input, const FeatureOptions& options, SurfaceFeatures& features,
                         FeatureCounts& counts) {
  std::optional<bool> input_crosses_itself;
  const double diagonal = bounding_box_diagonal(input);
  for (int rounds = options.smoothing_rounds; rounds > 0;) {
    SmoothingOptions smoothing;
    smoothing.max_iterations = rounds;
    smoothing.max_deviation = options.smoothing_tolerance * diagonal;
    SmoothedSurface smoothed = smooth_patches(input, features.strata, smoothing);
    if (smoothed.iterations == 0) break;
    rounds = smoothed.iterations - 1;  // the next try, if this one is refused
    // Where the input spikes, Loop's rules can fold a small face over its neighbours (a femur
    // scan, a valence-3 spike: a face of 5e-5 bent 127 degrees from each neighbour, which then
    // stood as creases protected by balls a millionth of the model). A surface declared smooth
    // keeps no fold past the sharp angle; another unfolds the faces folded over all their
    // neighbours. The features carried through stay put.
    const io::Unfolding unfolding = options.smooth
                                        ? io::flatten_folds(smoothed.mesh, options.sharp_angle, fixed_vertices(smoothed))
                                        : io::unfold_faces(smoothed.mesh, fixed_vertices(smoothed));
    // A smooth surface's features are found afresh after smoothing, so only the others are carried.
    std::optional<Strata> carried;
    if (!options.smooth) {
      carried = strata_after_smoothing(smoothed);
      const Strata fresh = detect_strata(smoothed.mesh, options.sharp_angle);
      if (fresh.sharp_edge != carried->sharp_edge || fresh.corners != carried->corners) {
        counts.smoothing_rounds_refused = smoothed.iterations;
        continue;
      }
    }
    if (!geometry::find_self_intersections(smoothed.mesh).empty()) {
      if (!input_crosses_itself) input_crosses_itself = !geometry::find_self_intersections(input).empty();
      if (!*input_crosses_itself) {
        counts.smoothing_rounds_crossing = smoothed.iterations;
        continue;
      }
    }
    if (!region_labels_hold(smoothed.mesh)) {
      counts.smoothing_rounds_crossing = smoothed.iterations;
      continue;
    }
    counts.smoothing_iterations = smoothed.iterations;
    counts.smoothing_faces_unfolded = unfolding.folded.size() - unfolding.remaining.size();
    counts.smoothing_bounding_rounds = smoothed.bounding_rounds;
    counts.smoothing_largest_offset = diagonal > 0 ? smoothed.largest_limit_offset / diagonal : 0;
    if (carried) features.strata = std::move(*carried);
    features.surface = std::move(smoothed.mesh);
    return;
  }
}

}  // namespace

SurfaceFeatures find_features(const SurfaceMesh& input, const FeatureOptions& options, Phases& phases,
                              FeatureCounts& counts) {
  SurfaceFeatures features;
  const FeatureDetection detection = options.smooth ? FeatureDetection::BoundaryOnly : FeatureDetection::SharpAndBoundary;
  features.strata =
      phases("features", [&] { return detect_strata(input, options.sharp_angle, detection, box_faces(input)); });
  features.surface = input;
  if (options.smoothing_rounds > 0) {
    phases("smoothing", [&] { smooth_within_rules(input, options, features, counts); });
  }
  if (options.smooth) {
    features.strata = phases("features", [&] { return detect_strata(features.surface, options.sharp_angle); });
  }
  for (bool sharp : features.strata.sharp_edge) counts.sharp_edges += sharp;
  counts.corners = features.strata.corners.size();
  counts.creases = features.strata.creases.size();
  counts.patches = features.strata.num_patches;
  counts.faces_after_smoothing = features.surface.num_faces();
  return features;
}

}  // namespace vorocrust
