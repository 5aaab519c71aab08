// Internal: rays against the faces of a triangle surface, through a bounding-volume tree.
//
// A hit records which side of the face the ray arrives from, and whether that can be told:
// a hit within a relative 1e-7 of an edge (where a neighbouring face may be the one that
// counts) or a ray within 1e-6 of the face's plane is not `clear`, and callers retry along
// another direction. Degenerate faces are never hit; their neighbours decide.
#pragma once

#include <array>
#include <limits>
#include <vector>

#include "geometry/box_tree.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::geometry {

struct RayHit {
  double t = std::numeric_limits<double>::infinity();  // distance along the unit direction
  Index face = 0;
  bool clear = false;
  bool from_front = false;  // the ray arrives from the side the face's normal points to
  bool found() const { return t < std::numeric_limits<double>::infinity(); }
};

// Directions spread over the sphere and away from the axes and the diagonals, for rays that
// must not graze the axis-aligned faces CAD models are full of.
inline constexpr std::array<std::array<double, 3>, 7> kGenericDirections = {{{0.267, 0.534, 0.802},
                                                                             {-0.802, 0.267, 0.534},
                                                                             {0.534, -0.802, 0.267},
                                                                             {-0.381, -0.598, 0.705},
                                                                             {0.705, -0.381, -0.598},
                                                                             {-0.598, 0.705, -0.381},
                                                                             {0.123, -0.457, -0.881}}};

class RayCaster {
 public:
  explicit RayCaster(const SurfaceMesh& mesh) : mesh_(mesh), faces_(face_tree(mesh)) {}

  // The nearest face the ray from p along `direction` meets (t > 0), or a hit with !found().
  RayHit first_hit(const Point& p, const Point& direction) const;

  // Every face the ray meets, nearest first.
  std::vector<RayHit> all_hits(const Point& p, const Point& direction) const;

  const SurfaceMesh& mesh() const { return mesh_; }

 private:
  // Calls visit(hit) for each face met with t in (0, limit()); limit may shrink between calls.
  template <class Limit, class Visit>
  void cast(const Point& p, const Point& direction, Limit&& limit, Visit&& visit) const;

  const SurfaceMesh& mesh_;
  BoxTree faces_;
};

}  // namespace vorocrust::geometry
