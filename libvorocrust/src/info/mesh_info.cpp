#include "vorocrust/mesh_info.hpp"

#include <algorithm>

#include "core/edge_topology.hpp"
#include "core/face_components.hpp"
#include "core/surface_measures.hpp"

namespace vorocrust {

MeshInfo mesh_info(const SurfaceMesh& mesh) {
  MeshInfo info;
  info.vertices = mesh.vertices.size();
  info.faces = mesh.triangles.size();
  for (const Point& p : mesh.vertices) info.bounding_box.extend(p);

  const EdgeTopology topo = build_edge_topology(mesh);
  info.edges = topo.num_edges();
  FaceComponents found = face_components(mesh, topo);
  std::vector<ComponentInfo>& parts = found.components;
  for (std::size_t c = 0; c < parts.size(); ++c) {
    ComponentInfo& part = parts[c];
    info.boundary_edges += part.boundary_edges;
    info.non_manifold_edges += part.non_manifold_edges;
    part.area = surface_area(mesh, found.faces[c]);
    info.area += part.area;
    if (part.closed() && part.manifold()) {
      part.genus = static_cast<int>((2 - part.euler_characteristic()) / 2);
      part.volume = enclosed_volume(mesh, found.faces[c]);
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
