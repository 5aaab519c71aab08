// Face skewness as checkMesh defines it (OpenFOAM's primitiveMesh face skewness).
#include "vorocrust/face_skewness.hpp"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

namespace vorocrust {

double face_skewness(const VoronoiMesh& mesh, std::size_t face) {
  constexpr double kTiny = 1e-300;
  const VoronoiFace& f = mesh.faces[face];
  const FaceGeometry g = face_geometry(mesh, face);
  const Point area = g.normal * g.area;
  const Point& own = mesh.cells[f.owner].centroid;
  const Point to_face = g.centroid - own;
  const Point link = f.neighbour != kNoCell ? Point(mesh.cells[f.neighbour].centroid - own)
                                            : Point(g.normal * g.normal.dot(to_face));
  const Point off = to_face - area.dot(to_face) / (area.dot(link) + kTiny) * link;
  const Point across = off / (off.norm() + kTiny);
  // A boundary face's link reaches only from the centroid to the face: checkMesh doubles its share.
  double reach = (f.neighbour != kNoCell ? 0.2 : 0.4) * link.norm() + kTiny;
  for (Index p : f.points) reach = std::max(reach, std::abs(across.dot(mesh.points[p] - g.centroid)));
  return off.norm() / reach;
}

std::vector<std::size_t> skew_faces(const VoronoiMesh& mesh, double threshold) {
  std::vector<char> skew(mesh.faces.size(), 0);
  tbb::parallel_for(std::size_t{0}, mesh.faces.size(),
                    [&](std::size_t f) { skew[f] = face_skewness(mesh, f) > threshold; });
  std::vector<std::size_t> out;
  for (std::size_t f = 0; f < skew.size(); ++f) {
    if (skew[f]) out.push_back(f);
  }
  return out;
}

}  // namespace vorocrust
