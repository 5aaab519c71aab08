// Sharp features and smooth patches of a surface: its strata (paper section 2.2).
//
// An edge is *sharp* when its two faces' normals differ by more than theta# (a dihedral angle
// below pi - theta#), or when it has one face (boundary) or more than two (non-manifold). A vertex
// is a *sharp corner* when it has more than two sharp edges, exactly one (a crease ending inside
// a smooth surface), two whose lines turn by more than theta#, or two faces in one sector (faces
// around it joined by non-sharp edges) whose normals differ by at least theta#. *Creases* are the
// chains of sharp edges between corners, or closed cycles; *patches* are the faces joined across
// non-sharp edges. Each crease is oriented from its first vertex to its last; patches keep the
// orientation of their faces.
#pragma once

#include <cstdint>
#include <vector>

#include "core/edge_topology.hpp"
#include "vorocrust/balls.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

struct Crease {
  std::vector<Index> vertices;  // in order; a cycle does not repeat its first vertex
  std::vector<Index> edges;     // edges[i] joins vertices[i] and vertices[i + 1] (cyclically if closed)
  bool closed = false;
};

struct Strata {
  static constexpr std::int32_t kNone = -1;

  EdgeTopology topology;
  std::vector<Point> face_normals;     // unit; zero for degenerate faces
  std::vector<bool> sharp_edge;        // per edge
  std::vector<std::int32_t> edge_crease;   // per edge: its crease, or kNone when not sharp
  std::vector<Point> edge_tangent;         // per edge: unit direction along its crease; zero if none
  std::vector<std::int32_t> vertex_corner; // per vertex: its corner, or kNone
  std::vector<Index> corners;              // vertex of each corner
  std::vector<Crease> creases;
  std::vector<Index> face_patch;           // per face: its patch
  std::size_t num_patches = 0;

  // Incidence between strata, for deciding whether a ball may reach into a higher stratum.
  std::vector<std::vector<Index>> corner_creases;  // creases ending at each corner
  std::vector<std::vector<Index>> corner_patches;  // patches with a face at each corner
  std::vector<std::vector<Index>> crease_patches;  // patches with a face along each crease
};

// Which edges may be sharp. A scan or a coarse tessellation of a curved shape bends by more than
// theta# between neighbouring faces without having a crease there (igl_bunny: 59 edges past 60
// degrees): smoothed as a smooth surface, its only fixed features are its boundary and
// non-manifold edges, with the corners where those end, branch or turn by more than theta#.
enum class FeatureDetection {
  SharpAndBoundary,  // the paper's rules: edges bent past theta#, sectors spread by theta#, and the boundary
  BoundaryOnly,      // the surface is smooth: nothing is sharp for its angle
};

// Detects the strata of `mesh` for the sharp angle theta# (radians, in (0, pi/2)). With
// BoundaryOnly, the edges of faces flagged in `judged_by_angle` (by face; empty for none) are
// still sharp past theta#: the sides of a box around a smooth model are no part of its smooth
// surface, and smoothed with it they would round into a blob through the model.
Strata detect_strata(const SurfaceMesh& mesh, double sharp_angle,
                     FeatureDetection detection = FeatureDetection::SharpAndBoundary,
                     const std::vector<bool>& judged_by_angle = {});

// The strata of `mesh` for sharp edges (by edge of its EdgeTopology) and corners decided already,
// as after smoothing, which carries the input's features through subdivision. Edges with other
// than two faces are sharp, and vertices with one or more than two sharp edges corners, anyway.
Strata build_strata(const SurfaceMesh& mesh, std::vector<bool> sharp_edge_by_topology_edge,
                    std::vector<bool> corner_by_vertex);

}  // namespace vorocrust
