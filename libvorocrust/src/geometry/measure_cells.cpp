#include "geometry/measure_cells.hpp"

#include <tbb/parallel_for.h>

#include "geometry/polygon_measures.hpp"

namespace vorocrust::geometry {

void measure_cells(VoronoiMesh& mesh) {
  tbb::parallel_for(std::size_t{0}, mesh.cells.size(), [&](std::size_t c) {
    VoronoiCell& cell = mesh.cells[c];
    const Point apex = mesh.points[mesh.faces[cell.faces.front()].points.front()];
    double volume = 0;
    Point moment = Point::Zero();
    for (Index id : cell.faces) {
      const VoronoiFace& face = mesh.faces[id];
      add_cone(
          apex, face.points.size(), [&](std::size_t k) -> const Point& { return mesh.points[face.points[k]]; },
          face.owner == static_cast<std::int32_t>(c), volume, moment);
    }
    cell.volume = volume;
    cell.centroid = moment / volume;
  });
}

}  // namespace vorocrust::geometry
