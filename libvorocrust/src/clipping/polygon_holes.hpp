// Internal: a plane region bounded by an outer loop and holes, as simple polygons over the same
// points. Exports take faces without holes (OpenFOAM, VTK polyhedra), and a point added to split
// a face would be a hanging point of the faces beside it; so each hole is joined to the outer
// loop by two diagonals between existing points, which cut the region in two, and the other
// holes go to the part that holds them.
//
// Contract of simple_polygons(loops, at, normal): the loops bound a region of a plane, disjoint,
// the outer ones counter-clockwise about `normal` and the holes clockwise, each hole inside an
// outer loop. `at(i)` is point i. Returns simple polygons, counter-clockwise, that tile the
// region and use its points only. Throws Error(Internal) when no pair of diagonals is free of the
// loops (loops that touch).
#pragma once

#include <functional>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::clipping {

using Loop = std::vector<Index>;

std::vector<Loop> simple_polygons(std::vector<Loop> loops, const std::function<const Point&(Index)>& at,
                                  const Point& normal);

}  // namespace vorocrust::clipping
