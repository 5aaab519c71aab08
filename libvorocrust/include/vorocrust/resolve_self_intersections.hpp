// vorocrust/resolve_self_intersections.hpp — a surface that cuts through itself, made into one
// that meets itself only along shared edges.
//
// resolve_self_intersections(mesh) splits every face along the curves where other faces cross
// it (the surface's arrangement), so that those curves become edges shared by all the faces
// that meet there: the features stage then sees them as non-manifold edges, creases the balls
// protect. It then decides which region of space each new piece of space belongs to:
// - every region R of the input (label_regions on the input as it is) claims the points its
//   boundary winds around at least once, counting the boundary faces with R on their inside;
// - a piece claimed by one region joins it; a piece claimed by several (a brain layer poking
//   through the skull around it, two overlapping solids) or by none joins the one that the
//   faces around it name over the largest area, among the claimants when there are any;
// - a face both of whose sides now face one region, though its input face parted two, lies
//   inside that region and is dropped (the overlap of two parts of one solid).
// The result carries the region of both sides of every face (face_regions, region_names), so
// label_regions() on it keeps them; faces keep the group and source line of the input face they
// came from.
//
// Points where faces cross are rounded to doubles; the result is checked with the exact
// self-intersection test and Error(InvalidGeometry) names the faces where a cut could not be
// made consistently, or where two faces overlap in a common plane, which has no curve to cut
// along. A mesh that does not cut itself is returned as it is.
#pragma once

#include "vorocrust/api.hpp"

#include <cstddef>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

struct VOROCRUST_API SelfIntersectionStats {
  std::size_t face_pairs = 0;     // pairs of input faces that crossed or touched
  std::size_t faces_cut = 0;      // input faces split along an intersection curve
  std::size_t points_added = 0;   // new vertices on the intersection curves
  std::size_t faces_dropped = 0;  // faces of the arrangement left inside one region
  std::size_t faces = 0;          // faces of the result
};

VOROCRUST_API SurfaceMesh resolve_self_intersections(const SurfaceMesh& mesh, SelfIntersectionStats* stats = nullptr);

}  // namespace vorocrust
