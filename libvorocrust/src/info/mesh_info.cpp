#include "vorocrust/mesh_info.hpp"

#include <algorithm>

#include "core/edge_topology.hpp"
#include "core/surface_measures.hpp"

namespace vorocrust {

MeshInfo mesh_info(const SurfaceMesh& mesh) {
  MeshInfo info;
  info.vertices = mesh.vertices.size();
  info.faces = mesh.triangles.size();
  for (const Point& p : mesh.vertices) info.bounding_box.extend(p);

  const EdgeTopology topo = build_edge_topology(mesh);
  info.edges = topo.num_edges();
  std::size_t count = 0;
  const std::vector<Index> component = label_face_components(mesh, topo, [](std::size_t) { return true; }, count);

  std::vector<ComponentInfo> parts(count);
  std::vector<std::vector<Index>> faces_of(count);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) faces_of[component[f]].push_back(static_cast<Index>(f));
  for (std::size_t e = 0; e < topo.num_edges(); ++e) {
    ComponentInfo& c = parts[component[topo.faces_of(e)[0]]];
    ++c.edges;
    if (topo.is_boundary(e)) ++c.boundary_edges, ++info.boundary_edges;
    if (topo.is_non_manifold(e)) ++c.non_manifold_edges, ++info.non_manifold_edges;
  }
  std::vector<Index> stamp(mesh.vertices.size(), ~Index{0});
  for (std::size_t c = 0; c < count; ++c) {
    ComponentInfo& part = parts[c];
    part.faces = faces_of[c].size();
    for (Index f : faces_of[c]) {
      for (Index v : mesh.triangles[f]) {
        if (stamp[v] != c) stamp[v] = static_cast<Index>(c), ++part.vertices;
      }
    }
    part.area = surface_area(mesh, faces_of[c]);
    info.area += part.area;
    if (part.closed() && part.manifold()) {
      const long euler = static_cast<long>(part.vertices) - static_cast<long>(part.edges) + static_cast<long>(part.faces);
      part.genus = static_cast<int>((2 - euler) / 2);
      part.volume = enclosed_volume(mesh, faces_of[c]);
    }
  }
  std::stable_sort(parts.begin(), parts.end(), [](const ComponentInfo& a, const ComponentInfo& b) { return a.faces > b.faces; });
  info.components = std::move(parts);
  if (std::all_of(info.components.begin(), info.components.end(), [](const ComponentInfo& c) { return c.genus.has_value(); })) {
    int genus = 0;
    for (const ComponentInfo& c : info.components) genus += *c.genus;
    info.genus = genus;
  }
  info.groups.reserve(mesh.groups.size());
  for (const FaceGroup& g : mesh.groups) info.groups.push_back({g.name, g.source_file, 0});
  for (Index g : mesh.face_group) ++info.groups[g].faces;
  return info;
}

}  // namespace vorocrust
