// Internal: exact intersection tests between two triangles, alone or as faces of one mesh.
//
// Contract: triangles are closed point sets, so touching counts as intersecting.
// `improperly_intersect` decides whether two faces of a mesh meet anywhere other than the
// vertex or edge they share *by index*; `shared` says which corners those are, and the shared
// corners must be bitwise-equal points (they are the same mesh vertex). Faces sharing no vertex
// are improper as soon as they have any point in common; faces at the same position but on
// different vertex indices are not "shared" and so do intersect.
// Every decision is made by the exact predicates of predicates.hpp, without tolerances, so the
// answer is exact for all inputs those predicates accept.
// Left to other checks, and answered `false` here: degenerate (zero-area) triangles, and faces
// sharing all three vertices (duplicate faces, in either orientation).
#pragma once

#include <array>
#include <optional>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::geometry {

using TriangleCorners = std::array<Point, 3>;

inline TriangleCorners corners_of(const SurfaceMesh& mesh, std::size_t face) {
  const Triangle& t = mesh.triangles[face];
  return {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
}

// shared[i] is the corner of the second face on the same mesh vertex as corner i of the first
// face, or -1 when corner i is not shared.
using SharedCorners = std::array<int, 3>;

inline constexpr SharedCorners kNoSharedCorners = {-1, -1, -1};

SharedCorners shared_corners(const Triangle& first, const Triangle& second);

// The two coordinates kept when a plane is projected along its third axis. The projection is a
// bijection of the plane iff the plane's normal has a nonzero component along the dropped axis;
// then 2D orientations of projected points of that plane are exact stand-ins for 3D ones.
struct Projection {
  int x, y;
};

// A projection that keeps t non-degenerate (the axis of t's largest normal component when that
// one certifiably works), or none when t has zero area.
std::optional<Projection> projection_of(const TriangleCorners& t);

// True when the three corners are collinear (including coincident), decided exactly.
bool is_degenerate(const TriangleCorners& t);

bool improperly_intersect(const TriangleCorners& t, const TriangleCorners& u,
                          const SharedCorners& shared);

// Whether two closed triangles have any point in common.
inline bool triangles_intersect(const TriangleCorners& t, const TriangleCorners& u) {
  return improperly_intersect(t, u, kNoSharedCorners);
}

}  // namespace vorocrust::geometry
