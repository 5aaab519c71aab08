// Feature detection (paper section 2.2).
#include <algorithm>
#include <cmath>

#include "core/surface_measures.hpp"
#include "features/strata.hpp"

namespace vorocrust {

namespace {

// Edges around each vertex, in compressed rows.
struct VertexEdges {
  std::vector<std::size_t> offsets;
  std::vector<Index> edges;
  std::span<const Index> of(Index v) const { return {edges.data() + offsets[v], offsets[v + 1] - offsets[v]}; }
};

VertexEdges vertex_edges(std::size_t num_vertices, const EdgeTopology& topo) {
  VertexEdges ve;
  ve.offsets.assign(num_vertices + 1, 0);
  for (const auto& e : topo.edges) ++ve.offsets[e[0] + 1], ++ve.offsets[e[1] + 1];
  for (std::size_t v = 0; v < num_vertices; ++v) ve.offsets[v + 1] += ve.offsets[v];
  ve.edges.resize(ve.offsets.back());
  std::vector<std::size_t> fill(ve.offsets.begin(), ve.offsets.end() - 1);
  for (Index e = 0; e < topo.edges.size(); ++e) {
    ve.edges[fill[topo.edges[e][0]]++] = e;
    ve.edges[fill[topo.edges[e][1]]++] = e;
  }
  return ve;
}

Index other_end(const EdgeTopology& topo, Index e, Index v) {
  return topo.edges[e][0] == v ? topo.edges[e][1] : topo.edges[e][0];
}

// Faces around `v` joined by its non-sharp edges form sectors; a sector whose normals spread by
// at least theta# has a cone point at v.
bool sector_spreads(const Strata& s, const VertexEdges& ve, Index v, double cos_sharp) {
  std::vector<Index> faces;
  for (Index e : ve.of(v)) {
    for (Index f : s.topology.faces_of(e)) faces.push_back(f);
  }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  // Union faces sharing a non-sharp edge at v.
  std::vector<std::size_t> parent(faces.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
  const auto find = [&](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  const auto slot = [&](Index f) { return static_cast<std::size_t>(std::lower_bound(faces.begin(), faces.end(), f) - faces.begin()); };
  for (Index e : ve.of(v)) {
    if (s.sharp_edge[e]) continue;
    const auto around = s.topology.faces_of(e);
    parent[find(slot(around[0]))] = find(slot(around[1]));
  }
  for (std::size_t i = 0; i < faces.size(); ++i) {
    for (std::size_t j = i + 1; j < faces.size(); ++j) {
      if (find(i) != find(j)) continue;
      if (s.face_normals[faces[i]].dot(s.face_normals[faces[j]]) <= cos_sharp) return true;
    }
  }
  return false;
}

void walk_crease(Strata& s, const VertexEdges& ve, Index start_vertex, Index first_edge, bool from_corner) {
  Crease crease;
  const std::int32_t id = static_cast<std::int32_t>(s.creases.size());
  Index v = start_vertex, e = first_edge;
  crease.vertices.push_back(v);
  while (true) {
    s.edge_crease[e] = id;
    crease.edges.push_back(e);
    v = other_end(s.topology, e, v);
    if (s.vertex_corner[v] != Strata::kNone) {  // reached a corner: the crease ends
      crease.vertices.push_back(v);
      break;
    }
    // A non-corner vertex on a crease has exactly two sharp edges: continue on the other one.
    Index next = e;
    for (Index candidate : ve.of(v)) {
      if (candidate != e && s.sharp_edge[candidate]) next = candidate;
    }
    if (next == e || s.edge_crease[next] == id) {  // back at the start of a cycle
      crease.closed = !from_corner;
      break;
    }
    crease.vertices.push_back(v);
    e = next;
  }
  s.creases.push_back(std::move(crease));
}

}  // namespace

namespace {

void compute_topology_and_normals(const SurfaceMesh& mesh, Strata& s) {
  s.topology = build_edge_topology(mesh);
  s.face_normals.resize(mesh.num_faces());
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) s.face_normals[f] = face_normal(mesh, static_cast<Index>(f));
}

// Creases, tangents, patches and incidences from sharp edges and corners already decided.
void complete_strata(const SurfaceMesh& mesh, Strata& s, const std::vector<bool>& corner_by_vertex) {
  const EdgeTopology& topo = s.topology;
  const VertexEdges ve = vertex_edges(mesh.num_vertices(), topo);
  s.vertex_corner.assign(mesh.num_vertices(), Strata::kNone);
  s.corners.clear();
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    std::size_t sharp = 0;
    for (Index e : ve.of(v)) sharp += s.sharp_edge[e];
    // A crease ends only at a corner: one sharp edge, or more than two, makes one.
    const bool forced = sharp == 1 || sharp > 2;
    if ((v < corner_by_vertex.size() && corner_by_vertex[v]) || forced) {
      s.vertex_corner[v] = static_cast<std::int32_t>(s.corners.size());
      s.corners.push_back(v);
    }
  }

  s.edge_crease.assign(topo.num_edges(), Strata::kNone);
  s.creases.clear();
  for (Index c = 0; c < s.corners.size(); ++c) {
    const Index v = s.corners[c];
    for (Index e : ve.of(v)) {
      if (s.sharp_edge[e] && s.edge_crease[e] == Strata::kNone) walk_crease(s, ve, v, e, true);
    }
  }
  for (Index e = 0; e < topo.num_edges(); ++e) {
    if (s.sharp_edge[e] && s.edge_crease[e] == Strata::kNone) walk_crease(s, ve, topo.edges[e][0], e, false);
  }

  s.edge_tangent.assign(topo.num_edges(), Point::Zero());
  for (const Crease& c : s.creases) {
    for (std::size_t i = 0; i < c.edges.size(); ++i) {
      const Point from = mesh.vertices[c.vertices[i]], to = mesh.vertices[c.vertices[(i + 1) % c.vertices.size()]];
      s.edge_tangent[c.edges[i]] = (to - from).normalized();
    }
  }

  s.face_patch = label_face_components(mesh, topo, [&](std::size_t e) { return !s.sharp_edge[e]; }, s.num_patches);

  s.corner_creases.assign(s.corners.size(), {});
  s.corner_patches.assign(s.corners.size(), {});
  s.crease_patches.assign(s.creases.size(), {});
  for (Index k = 0; k < s.creases.size(); ++k) {
    const Crease& crease = s.creases[k];
    if (!crease.closed) {
      for (Index v : {crease.vertices.front(), crease.vertices.back()}) s.corner_creases[s.vertex_corner[v]].push_back(k);
    }
    for (Index e : crease.edges) {
      for (Index f : topo.faces_of(e)) s.crease_patches[k].push_back(s.face_patch[f]);
    }
  }
  for (Index c = 0; c < s.corners.size(); ++c) {
    for (Index e : ve.of(s.corners[c])) {
      for (Index f : topo.faces_of(e)) s.corner_patches[c].push_back(s.face_patch[f]);
    }
  }
  const auto dedupe = [](std::vector<std::vector<Index>>& lists) {
    for (auto& l : lists) {
      std::sort(l.begin(), l.end());
      l.erase(std::unique(l.begin(), l.end()), l.end());
    }
  };
  dedupe(s.corner_creases);
  dedupe(s.corner_patches);
  dedupe(s.crease_patches);
}

}  // namespace

Strata build_strata(const SurfaceMesh& mesh, std::vector<bool> sharp_edge_by_topology_edge,
                    std::vector<bool> corner_by_vertex) {
  Strata s;
  compute_topology_and_normals(mesh, s);
  s.sharp_edge = std::move(sharp_edge_by_topology_edge);
  s.sharp_edge.resize(s.topology.num_edges(), false);
  for (std::size_t e = 0; e < s.topology.num_edges(); ++e) {
    if (s.topology.valence(e) != 2) s.sharp_edge[e] = true;
  }
  complete_strata(mesh, s, corner_by_vertex);
  return s;
}

Strata detect_strata(const SurfaceMesh& mesh, double sharp_angle, FeatureDetection detection,
                     const std::vector<bool>& judged_by_angle) {
  const bool by_angle = detection == FeatureDetection::SharpAndBoundary;
  const auto judged = [&](Index f) { return by_angle || (f < judged_by_angle.size() && judged_by_angle[f]); };
  Strata s;
  compute_topology_and_normals(mesh, s);
  const EdgeTopology& topo = s.topology;
  const double cos_sharp = std::cos(sharp_angle);

  s.sharp_edge.assign(topo.num_edges(), false);
  for (std::size_t e = 0; e < topo.num_edges(); ++e) {
    if (topo.valence(e) != 2) {
      s.sharp_edge[e] = true;
      continue;
    }
    const auto faces = topo.faces_of(e);
    // Validation made faces across a manifold edge consistent, so their normals compare directly.
    double cos_angle = s.face_normals[faces[0]].dot(s.face_normals[faces[1]]);
    const auto [a, b] = topo.edges[e];
    if (edge_direction(mesh.triangles[faces[0]], a, b) == edge_direction(mesh.triangles[faces[1]], a, b)) {
      cos_angle = -cos_angle;  // inconsistent neighbours (a non-orientable patch): compare as lines
    }
    s.sharp_edge[e] = (judged(faces[0]) || judged(faces[1])) && cos_angle < cos_sharp;
  }

  const VertexEdges ve = vertex_edges(mesh.num_vertices(), topo);
  std::vector<bool> corner(mesh.num_vertices(), false);
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    if (ve.of(v).empty()) continue;  // a vertex no face uses
    std::vector<Index> sharp;
    for (Index e : ve.of(v)) {
      if (s.sharp_edge[e]) sharp.push_back(e);
    }
    bool is_corner = sharp.size() == 1 || sharp.size() > 2;
    if (sharp.size() == 2) {
      const Point a = (mesh.vertices[other_end(topo, sharp[0], v)] - mesh.vertices[v]).normalized();
      const Point b = (mesh.vertices[other_end(topo, sharp[1], v)] - mesh.vertices[v]).normalized();
      // The crease goes straight on when a and b are opposite; it turns by the angle between b and -a.
      is_corner = (-a).dot(b) < cos_sharp;
    }
    if (!is_corner && by_angle) is_corner = sector_spreads(s, ve, v, cos_sharp);
    corner[v] = is_corner;
  }
  complete_strata(mesh, s, corner);
  return s;
}

}  // namespace vorocrust
