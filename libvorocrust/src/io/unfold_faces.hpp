// Internal: faces folded over all their neighbours, unfolded.
//
// A face is *folded* when its normal turns by more than kFoldDegrees from the normal of the face
// across each of its manifold edges (at least two of them): the surface turns back on itself over
// that face, an inverted triangle. Decimated scans have them (igl_camelhead: two, the held-out
// elk scan three), and Loop's rules can make one where a scan spikes (a femur scan, smoothed).
// No surface the paper's sampling can cover has one: the sheets on either side meet at an angle
// near zero over a distance near zero, so balls there shrink without end (the refinement gave up
// on igl_camelhead; on the smoothed femur it protected the fold as creases with balls a
// millionth of the model, and the cells of such seeds no longer agreed after welding).
//
// Contract of unfold_faces(mesh, fixed): moves the free corners of folded faces (not `fixed`,
// not on a boundary or non-manifold edge) in turns, each to where its faces bend least (searched
// from where it is and from the centroid of its neighbours), until no turn lowers the largest
// bend about the fold; up to kUnfoldRounds rounds while any face is folded. No place is taken
// where one of the vertex's faces is flatter (height over longest edge) than a twentieth, or than
// the flattest of them was. A move that would fold another face, or make one of the vertex's faces
// cross a face it did not cross (exactly decided), is not made. Faces, their order and their
// vertices' indices stay. Returns the faces found folded first, whether all were unfolded, and how
// far the farthest vertex moved. Moves stay within the folded faces' one rings: a change of the
// size of the defect.
#pragma once

#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::io {

inline constexpr double kFoldDegrees = 120;
inline constexpr int kUnfoldRounds = 8;

struct Unfolding {
  std::vector<Index> folded;     // the faces folded before, ascending
  std::vector<Index> remaining;  // those still folded after (none when all were unfolded)
  std::size_t moved_vertices = 0;
  double largest_move = 0;
};

// The faces of `mesh` folded over all their neighbours, ascending.
std::vector<Index> folded_faces(const SurfaceMesh& mesh);

Unfolding unfold_faces(SurfaceMesh& mesh, const std::vector<bool>& fixed = {});

// The same moves for the faces with an edge bent by more than `max_bend` (radians): a surface
// declared smooth, once smoothed, has no fold past the sharp angle that is not a feature it
// carried (`fixed`), or its features would be folds a fraction of its edges long (Loop's rules
// about a spike of a scan leave such a fin). `folded` lists the faces so bent before.
Unfolding flatten_folds(SurfaceMesh& mesh, double max_bend, const std::vector<bool>& fixed = {});

}  // namespace vorocrust::io
