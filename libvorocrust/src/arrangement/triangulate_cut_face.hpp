// Internal: one face split along the curves that cut it (arrangement, before the features 2.2).
//
// The face's pieces triangulate it with every point of its FaceCut as a vertex and every cut
// segment as an edge: a constrained triangulation made in the face's plane, projected along its
// normal's largest axis, whose orientation tests are exact on the rounded points. Edges no cut
// constrains are flipped towards Delaunay, which keeps the pieces from being needlessly thin.
// The pieces keep the face's orientation. Throws Error(InvalidGeometry) naming the face when
// rounding has left a point or a segment where no consistent triangulation takes it (two
// segments crossing without a shared point, a point outside the face).
#pragma once

#include <vector>

#include "arrangement/face_cuts.hpp"

namespace vorocrust::arrangement {

std::vector<Triangle> triangulate_cut_face(const SurfaceMesh& mesh, Index face, const FaceCut& cut,
                                           const std::vector<Point>& points);

}  // namespace vorocrust::arrangement
