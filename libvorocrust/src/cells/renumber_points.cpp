#include "cells/renumber_points.hpp"

#include <limits>
#include <utility>
#include <vector>

namespace vorocrust::cells {

void renumber_points(VoronoiMesh& mesh) {
  constexpr Index kUnused = std::numeric_limits<Index>::max();
  std::vector<Index> renumber(mesh.points.size(), kUnused);
  std::vector<Point> points;
  points.reserve(mesh.points.size());
  for (VoronoiFace& f : mesh.faces) {
    for (Index& p : f.points) {
      if (renumber[p] == kUnused) {
        renumber[p] = static_cast<Index>(points.size());
        points.push_back(mesh.points[p]);
      }
      p = renumber[p];
    }
  }
  mesh.points = std::move(points);
}

}  // namespace vorocrust::cells
