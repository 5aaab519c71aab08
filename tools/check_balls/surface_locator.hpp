// check_balls/surface_locator.hpp — the nearest corner, crease edges and faces to a point.
//
// Contract: each query returns the exact Euclidean distance from x to the nearest element of its
// kind (infinity when there is none) and every element within `slack` of that distance, so a point
// on a shared vertex or edge sees all the elements it lies on. Distances to triangles and segments
// are computed plainly: projection when it falls inside, else the nearest boundary segment.
#pragma once

#include <limits>
#include <vector>

#include "check_balls/sphere_index.hpp"
#include "check_balls/strata.hpp"

namespace vorocrust::checker {

double distance_to_segment(const Point& x, const Point& a, const Point& b);
double distance_to_triangle(const Point& x, const Point& a, const Point& b, const Point& c);

struct Nearest {
  double distance = std::numeric_limits<double>::infinity();
  std::vector<Index> elements;  // corners, sharp edges or faces, in increasing index
};

class SurfaceLocator {
 public:
  SurfaceLocator(const SurfaceMesh& mesh, const Strata& strata);

  Nearest nearest_corner(const Point& x, double slack) const;
  Nearest nearest_sharp_edge(const Point& x, double slack) const;
  Nearest nearest_face(const Point& x, double slack) const;

 private:
  template <class Distance>
  Nearest nearest(const SphereIndex& index, const Point& x, double slack, Distance&& distance) const;

  const SurfaceMesh& mesh_;
  const Strata& strata_;
  std::vector<Index> sharp_edges_;
  SphereIndex corners_, sharp_edges_index_, faces_;
};

}  // namespace vorocrust::checker
