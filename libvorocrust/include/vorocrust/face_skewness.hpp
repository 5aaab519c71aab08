// vorocrust/face_skewness.hpp — skewness of the faces of a Voronoi mesh, as OpenFOAM's
// checkMesh measures it.
//
// For a face between two cells, the link between the two cells' centroids crosses the face's
// plane at some point; skewness is the distance from that point to the face's centroid over the
// larger of a fifth of the link's length and the face's extent in that direction. A boundary
// face uses its owner's centroid projected onto its plane, and two fifths of that shorter link. checkMesh calls a face highly skew
// above 4 and fails the mesh then. Voronoi faces are orthogonal to the links between the seeds,
// not the centroids, so skewness measures how far each cell's centroid lies from its seed.
#pragma once

#include "vorocrust/api.hpp"

#include <cstddef>
#include <vector>

#include "vorocrust/cells.hpp"

namespace vorocrust {

inline constexpr double kHighSkewness = 4;  // checkMesh's threshold

VOROCRUST_API double face_skewness(const VoronoiMesh& mesh, std::size_t face);

// The faces whose skewness exceeds `threshold`, in face order.
VOROCRUST_API std::vector<std::size_t> skew_faces(const VoronoiMesh& mesh, double threshold = kHighSkewness);

}  // namespace vorocrust
