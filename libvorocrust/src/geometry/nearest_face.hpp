// Internal: the face of a surface nearest a point, and the faces that bound a material.
//
// Contract: nearest_face searches a BoxTree whose items are face indices of `mesh` (face_tree,
// or boundary_tree for one material) and returns the nearest face that `accept` takes, with its
// squared distance: exact up to rounding, ties to the face met first in the tree's fixed order,
// {BoxTree::kNoItem, infinity} when no face is taken. `good_enough` stops the search as
// BoxTree::nearest does.
#pragma once

#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "geometry/box_tree.hpp"
#include "geometry/closest_point.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::geometry {

// Whether a face with regions `r` parts `material` from another region: a face with the material
// on both sides, or between two others, does not bound it.
inline bool bounds_material(const RegionPair& r, std::int32_t material) {
  return (r.back == material) != (r.front == material);
}

inline Point closest_on_face(const SurfaceMesh& mesh, std::uint32_t face, const Point& p) {
  const Triangle& t = mesh.triangles[face];
  return closest_on_triangle(p, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
}

struct EveryFace {
  bool operator()(std::uint32_t) const { return true; }
};

template <class Accept = EveryFace>
std::pair<std::uint32_t, double> nearest_face(const BoxTree& faces, const SurfaceMesh& mesh, const Point& p,
                                              Accept&& accept = {}, double good_enough = -1) {
  return faces.nearest(
      p,
      [&](std::uint32_t f) {
        return accept(f) ? (closest_on_face(mesh, f, p) - p).squaredNorm() : std::numeric_limits<double>::infinity();
      },
      good_enough);
}

// A tree over the faces of `mesh` that bound `material`: a box none of them crosses lies wholly
// inside the material or outside it, whatever other regions' faces cross it.
inline BoxTree boundary_tree(const SurfaceMesh& mesh, std::int32_t material) {
  std::vector<Box> boxes(mesh.num_faces());
  std::vector<std::uint32_t> faces;
  for (std::uint32_t f = 0; f < mesh.num_faces(); ++f) {
    if (!bounds_material(mesh.face_regions[f], material)) continue;
    for (Index v : mesh.triangles[f]) boxes[f].include(mesh.vertices[v]);
    faces.push_back(f);
  }
  return {std::move(boxes), std::move(faces)};
}

}  // namespace vorocrust::geometry
