#include "cell_figures.hpp"

#include "vorocrust/face_skewness.hpp"

namespace vorocrust::cli {

void print_face_figures(const CellQuality& q, std::FILE* to) {
  const char* prefix = to == stderr ? "vorocrust: " : "";
  std::fprintf(to, "%sfaces orthogonal to their seed links within %.2g deg (face %zu); against the cell centroids, "
               "as checkMesh measures: non-orthogonality max %.3g deg, mean %.3g deg, skewness max %.3g, %zu faces "
               "above %g\n", prefix, q.max_link_angle, q.link_angle_face, q.max_non_orthogonality,
               q.mean_non_orthogonality, q.max_skewness, q.highly_skew_faces, kHighSkewness);
}

}  // namespace vorocrust::cli
