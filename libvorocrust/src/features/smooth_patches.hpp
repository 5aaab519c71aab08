// Patch smoothing by adaptive Loop subdivision (paper section 2.2, "Patch Smoothing").
//
// Contract of smooth_patches(mesh, strata, options):
// - Runs at most `max_iterations` rounds. A round marks every face that has a non-sharp edge
//   whose dihedral angle (pi minus the angle between the two face normals) is below
//   `flat_dihedral_degrees`, closes the marking so the result is conforming, and subdivides.
//   It stops early after a round that marks nothing, and before a round that would take the
//   mesh past `max_faces` faces (that round is not applied).
// - Conformity is red-green refinement (Bank, Sherman and Weiser) with green removal: a face with
//   two or three split edges is split 1->4 (red), one with exactly one split edge is bisected
//   1->2 (green). A green pair is never split again: when either half would be split in a later
//   round (it is marked, or one of its edges is split), the pair is merged back into its parent
//   and the parent is split red, reusing the midpoint the pair already has; a half of that red
//   split whose outer edge (half of the old green edge) is split in the same round is bisected
//   green. So every face is a red descendant of an input face or one green bisection of one, and
//   the output has no T-junction: an edge has exactly the faces a conforming mesh would give it.
// - Sharp edges (those of `strata`, which include every boundary and non-manifold edge) are split
//   at their exact midpoint, so every crease vertex stays on the input's straight crease edge.
//   Non-sharp edges (always manifold) get Loop's edge point 3/8 (a + b) + 1/8 (c + d), c and d
//   the vertices opposite the edge; for an edge of a green half that is a whole edge of its
//   parent, the parent's opposite vertex is used, as the edge belongs to the parent's level.
//   Next to a vertex that may not move, Loop's rule would grow a ridge or a spike there, so:
//   an edge from a crease vertex or a corner on two or more sharp edges uses the crease/corner
//   rule of Biermann, Levin and Zorin (2000), (3/4 - g) v + g r + 1/8 (c + d) with
//   g = 1/2 - 1/4 cos(alpha / k) for the k faces spanning the angle alpha at v between its
//   sharp edges (exactly Loop's rule on a flat regular crease); an edge from a corner with at
//   most one sharp edge (a cone point, a crease ending inside a patch) or from a pinch is split
//   at its midpoint, so that fan stays the input's cone.
// - Vertices on a sharp edge, corners, and vertices where the surface is pinched (several fans)
//   never move. Every other vertex of a face split in the round moves by Loop's original vertex
//   rule (Loop 1987): v' = (1 - n beta) v + beta sum(neighbours), with
//   beta = (5/8 - (3/8 + 1/4 cos(2 pi / n))^2) / n over its n neighbours in the (conforming)
//   mesh at the start of the round. Positions are computed from the old ones all at once.
// - Kink guard: after each round no non-sharp edge may bend more than the input's worst
//   non-sharp edge (nor than pi - flat_dihedral); where Loop's stencils would do so (skinny or
//   folded input faces), the vertices of the two faces fall back to linear subdivision (edge
//   midpoints, old vertices in place), which only repeats bends that were there. So the largest
//   bend inside patches never grows, no face folds over, and no face ends with zero area unless
//   the input face it comes from had none.
// - Bounding rounds: with max_deviation > 0, before Loop's rounds, up to max_bounding_rounds
//   rounds split (red-green, as above) the faces around each free vertex whose limit point under
//   Loop's rules lies farther than max_deviation along its normal, at edge midpoints with nothing
//   moved. Splitting every edge at a vertex halves how far Loop's rules then move it, so a coarse
//   tessellation of a strongly bent shape (directional_bimba: 697 vertices, folds up to 129
//   degrees) is smoothed into a surface near it instead of shrunk away from it; where the
//   tessellation is fine for its bends, nothing is split. max_deviation is a target, not a bound:
//   a vertex Loop would move by more than 2^max_bounding_rounds times it still moves by more
//   (largest_limit_offset says how far the farthest one goes), and the limit surface between
//   vertices is judged by its vertices only. These rounds are not counted in `iterations`, and
//   none runs when max_iterations is 0.
// - Input vertices keep their indices (new ones are appended), children inherit their parent's
//   group, source line and region pair, and keep its orientation. Subdivision changes no
//   topology: components, boundaries, non-manifold edges and Euler characteristics stay.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "features/strata.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

struct SmoothingOptions {
  int max_iterations = 6;
  double flat_dihedral_degrees = 175.0;  // faces whose every non-sharp edge is at least this flat are not split
  std::size_t max_faces = 2'000'000;     // stop refining before exceeding this many faces
  double max_deviation = 0;              // bounding rounds' limit on Loop's move of a vertex; 0: none
  int max_bounding_rounds = 2;
};

struct SmoothedSurface {
  SurfaceMesh mesh;                               // original vertices keep their indices; new ones are appended
  std::vector<std::array<Index, 2>> sharp_edges;  // the input's sharp edges, subdivided (as vertex pairs, sorted)
  std::vector<Index> corners;                     // the input's corners (same vertex indices as before)
  int iterations = 0;                             // Loop rounds that split at least one face
  int bounding_rounds = 0;                        // midpoint rounds before them
  // After those, the farthest any vertex's limit point lies from it along its normal (0 without
  // max_deviation).
  double largest_limit_offset = 0;
  std::size_t faces_split = 0;                    // faces replaced by their children, summed over rounds
};

SmoothedSurface smooth_patches(const SurfaceMesh& mesh, const Strata& strata, const SmoothingOptions& options = {});

// The strata of a smoothed surface: its sharp edges and corners are the ones carried through
// subdivision, not detected again (the smoothed patches must not grow new creases).
Strata strata_after_smoothing(const SmoothedSurface& smoothed);

}  // namespace vorocrust
