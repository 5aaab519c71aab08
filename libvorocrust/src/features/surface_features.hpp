// Features (paper 2.2): the surface the balls will cover, and its strata.
//
// Contract of find_features(input, options, phases, counts):
// - Without smoothing: `input` itself, its strata detected at options.sharp_angle (sharp edges by
//   the normals' deviation, and boundary edges; with `smooth`, boundary and non-manifold edges
//   only, so the folds of a scan's tessellation are no creases). A box's sides are no part of a
//   smooth surface: their edges stay creases.
// - With options.smoothing_rounds > 0: the patches smoothed by adaptive Loop subdivision
//   (smooth_patches.hpp), at most that many rounds, fewer when more would make a sharp feature
//   the input lacks, carry the surface through itself (unless the input already crossed itself),
//   or carry a shell wholly across another (which leaves the regions' labels on the wrong sides);
//   every refused round count is tried one lower, down to none. With `smooth`, the features are
//   detected afresh on the smoothed surface: a fold that still bends past the sharp angle is a
//   crease after all.
// - `counts` gets the features found and what smoothing kept and refused; `phases` times
//   "features" and "smoothing".
#pragma once

#include "core/phases.hpp"
#include "features/strata.hpp"
#include "vorocrust/stats.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

struct FeatureOptions {
  double sharp_angle = 0;  // theta#, in radians
  bool smooth = false;     // the input approximates a smooth surface (MeshOptions::smooth)
  int smoothing_rounds = 0;
  double smoothing_tolerance = 0;  // as a fraction of the input's bounding-box diagonal
};

struct SurfaceFeatures {
  SurfaceMesh surface;  // the input, after patch smoothing
  Strata strata;        // its corners, creases and patches
};

SurfaceFeatures find_features(const SurfaceMesh& input, const FeatureOptions& options, Phases& phases,
                              FeatureCounts& counts);

}  // namespace vorocrust
