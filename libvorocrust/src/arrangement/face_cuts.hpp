// Internal: where the faces of a surface cut each other (arrangement, before the features 2.2).
//
// Two faces that cross meet along a segment of the line where their planes cross. Its ends are
// points where an edge of one face passes through the other: through its inside, across one of
// its edges, or at a vertex. Every such point is named by what it lies on (an edge and a face,
// two edges, an input vertex, or three faces where two intersection curves cross) so that each
// face holding it refers to one and the same new vertex; a point on an edge belongs to every
// face around that edge. Whether and where an edge passes through a face is decided with the
// exact predicates; only the positions of the new points are rounded.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "geometry/self_intersections.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::arrangement {

// What one face is cut by. Indices refer to FaceCuts::points.
struct FaceCut {
  // Points on each edge (corner i to corner i + 1), in order from corner i.
  std::array<std::vector<Index>, 3> edge_points;
  std::vector<Index> inner_points;
  // Segments of intersection curves that must become edges of the face's pieces.
  std::vector<std::array<Index, 2>> segments;
};

struct FaceCuts {
  std::vector<Point> points;        // the input's vertices, then the new points
  std::vector<Index> cut_faces;     // the faces that must be split, ascending
  std::vector<FaceCut> of_cut_face; // parallel to cut_faces
};

// `pairs`: every pair of faces that meet improperly (find_self_intersections). Throws
// Error(InvalidGeometry) for faces overlapping in a common plane and for distinct vertices at
// one position, neither of which has a curve to cut along.
FaceCuts find_face_cuts(const SurfaceMesh& mesh, std::span<const geometry::FacePair> pairs);

}  // namespace vorocrust::arrangement
