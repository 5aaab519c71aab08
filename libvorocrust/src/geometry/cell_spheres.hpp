// Internal: the two spheres of a convex cell's aspect ratio (paper section 3), over any source of
// faces: the welded cells of a mesh (cell_quality.cpp) and the cells as Voro++ cut them, before
// welding (cells::GrowingCells::long_cells, which splits cells too long), give the same figure
// from one code.
//
// cell_spheres(points, faces, size, at): `points` the cell's distinct points, `faces` its face
// count, `size(f)` the points of face f and `at(f, k)` its k-th point in order round it.
#pragma once

#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include "geometry/spheres.hpp"

namespace vorocrust::geometry {

struct CellSpheres {
  Sphere outer;  // the smallest enclosing the cell
  Sphere inner;  // the largest inside it
  double aspect_ratio() const {
    return inner.radius > 0 ? outer.radius / inner.radius : std::numeric_limits<double>::infinity();
  }
};

template <class Size, class At>
CellSpheres cell_spheres(std::vector<Point> points, std::size_t faces, Size&& size, At&& at) {
  Point mean = Point::Zero();
  for (const Point& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  double extent = 0;
  for (const Point& p : points) extent = std::max(extent, (p - mean).norm());

  // Face planes from their polygons (Newell's normal, turned away from the points' mean, which is
  // inside the convex cell), each moved out to the farthest cell point: the plane of a tiny face,
  // whose normal rounding may tilt, then never cuts into the cell.
  std::vector<Plane> planes;
  planes.reserve(faces);
  for (std::size_t f = 0; f < faces; ++f) {
    const std::size_t n = size(f);
    Point normal = Point::Zero(), centre = Point::Zero();
    for (std::size_t k = 0; k < n; ++k) {
      const Point a = at(f, k) - mean, b = at(f, (k + 1) % n) - mean;
      normal += a.cross(b);
      centre += a;
    }
    const double length = normal.norm();
    if (!(length > 0)) continue;
    normal /= length;
    if (normal.dot(centre) < 0) normal = -normal;
    double offset = -std::numeric_limits<double>::infinity();
    for (const Point& p : points) offset = std::max(offset, normal.dot(p - mean));
    planes.push_back({normal, offset + normal.dot(mean)});
  }

  CellSpheres spheres;
  spheres.outer = smallest_enclosing_sphere(std::move(points));
  spheres.inner = extent > 0 ? largest_inscribed_ball(planes, mean, extent) : Sphere{mean, 0};
  return spheres;
}

}  // namespace vorocrust::geometry
