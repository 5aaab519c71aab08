// Internal: the edges of a triangle soup and the faces around each, in compressed rows.
//
// Unlike a halfedge structure this holds any number of faces per edge, so boundary edges (one
// face) and non-manifold edges (three or more) are represented as they are.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

struct EdgeTopology {
  std::vector<std::array<Index, 2>> edges;  // (smaller, larger) vertex index, sorted
  std::vector<std::size_t> face_offsets;    // faces of edge e: edge_faces[face_offsets[e] .. face_offsets[e+1])
  std::vector<Index> edge_faces;
  std::vector<std::array<Index, 3>> face_edges;  // per face: edges (t0,t1), (t1,t2), (t2,t0)

  std::size_t num_edges() const { return edges.size(); }
  std::size_t valence(std::size_t e) const { return face_offsets[e + 1] - face_offsets[e]; }
  std::span<const Index> faces_of(std::size_t e) const {
    return {edge_faces.data() + face_offsets[e], valence(e)};
  }
  bool is_boundary(std::size_t e) const { return valence(e) == 1; }
  bool is_non_manifold(std::size_t e) const { return valence(e) > 2; }
};

EdgeTopology build_edge_topology(const SurfaceMesh& mesh);

// Labels faces 0..count-1 by the component they belong to, joining faces across every edge
// for which `joins(e)` holds. Components are numbered in order of their smallest face.
template <class JoinPredicate>
std::vector<Index> label_face_components(const SurfaceMesh& mesh, const EdgeTopology& topology,
                                         JoinPredicate joins, std::size_t& count);

// +1 when `face` runs along edge (a, b) from a to b, -1 when from b to a.
int edge_direction(const Triangle& face, Index a, Index b);

}  // namespace vorocrust

#include "core/edge_topology_impl.hpp"
