// check_balls/strata.hpp — the checker's own strata: sharp edges, corners, creases, patches.
//
// Contract: find_strata() follows docs/ball-conditions.md word for word, written independently of
// libvorocrust/src/features so the two can be compared. Choices the contract leaves open:
// - an edge joining a vertex to itself (a face with a repeated corner) is ignored;
// - a face of zero area has a zero normal; an angle involving a zero vector counts as 0, so such a
//   face never makes an edge sharp nor a vertex a corner, and it gives no direction;
// - creases and patches are numbered in order of their lowest edge or face index, a crease is
//   oriented from its first corner (or, for a cycle, along its lowest edge).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "check_balls/check_balls.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::checker {

inline constexpr Index kNone = std::numeric_limits<Index>::max();

struct StratumRef {
  StratumType type = StratumType::Patch;
  Index index = kNone;
  friend bool operator==(const StratumRef&, const StratumRef&) = default;
};

struct SurfaceEdge {
  Index a = 0, b = 0;        // a < b
  std::vector<Index> faces;  // every face with this edge
};

struct Strata {
  std::vector<Point> face_normal;              // unit, or zero for a face of zero area
  std::vector<SurfaceEdge> edges;
  std::vector<std::array<Index, 3>> face_edges;  // edge of (v0 v1), (v1 v2), (v2 v0); kNone if degenerate
  std::vector<std::vector<Index>> vertex_edges;
  std::vector<std::vector<Index>> vertex_faces;
  std::vector<bool> sharp;                     // per edge

  std::vector<Index> corner_vertex;            // corner -> vertex
  std::vector<Index> vertex_corner;            // vertex -> corner or kNone

  std::vector<std::vector<Index>> crease_edges;    // in chain order
  std::vector<std::vector<Index>> crease_corners;  // the corners at its ends, sorted, unique
  std::vector<Index> edge_crease;                  // sharp edge -> crease, else kNone
  std::vector<Point> edge_direction;               // unit, along its crease's orientation (sharp edges)
  std::vector<Index> vertex_crease;                // non-corner vertex on a crease -> crease, else kNone

  std::vector<Index> face_patch;
  std::size_t num_patches = 0;
  std::vector<std::vector<Index>> patch_creases;   // sorted, unique
  std::vector<std::vector<Index>> patch_corners;   // sorted, unique

  std::size_t num_corners() const { return corner_vertex.size(); }
  std::size_t num_creases() const { return crease_edges.size(); }

  // Whether `higher` (of higher dimension) is incident to `lower`, per the contract.
  bool incident(StratumRef higher, StratumRef lower) const;
};

// The angle in [0, pi] between two vectors; 0 when either is zero.
double angle_between(const Point& u, const Point& v);

Strata find_strata(const SurfaceMesh& mesh, double sharp_angle_radians);

}  // namespace vorocrust::checker
