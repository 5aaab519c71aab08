// vorocrust/openmesh.hpp — SurfaceMesh <-> OpenMesh TriMesh, for programs that hold OpenMesh meshes.
//
// Header-only, so libvorocrust itself does not tie its users to OpenMesh; include it after
// OpenMesh's own headers are reachable (target OpenMeshCore).
//
// to_openmesh() needs a mesh OpenMesh can hold: every edge with at most two faces and every
// vertex a single fan. A face OpenMesh refuses is not dropped silently: the conversion throws
// Error(InvalidGeometry) naming it. from_openmesh() keeps every face and vertex in order.
#pragma once

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <string>
#include <vector>

#include "vorocrust/error.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

using OpenMeshTriMesh = OpenMesh::TriMesh_ArrayKernelT<OpenMesh::DefaultTraitsDouble>;

inline OpenMeshTriMesh to_openmesh(const SurfaceMesh& mesh) {
  OpenMeshTriMesh out;
  std::vector<OpenMeshTriMesh::VertexHandle> handles;
  handles.reserve(mesh.vertices.size());
  for (const Point& p : mesh.vertices) {
    handles.push_back(out.add_vertex(OpenMeshTriMesh::Point(p.x(), p.y(), p.z())));
  }
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const auto face = out.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
    if (!face.is_valid()) {
      throw Error(Error::Kind::InvalidGeometry,
                  "OpenMesh cannot hold " + describe_face(mesh, f) +
                      ": it would make a non-manifold edge or vertex; keep such meshes as "
                      "SurfaceMesh",
                  {.face = f});
    }
  }
  return out;
}

inline SurfaceMesh from_openmesh(const OpenMeshTriMesh& in, const std::string& group_name = "openmesh") {
  SurfaceMesh mesh;
  mesh.groups.push_back({group_name, {}});
  mesh.vertices.reserve(in.n_vertices());
  for (const auto v : in.vertices()) {
    const auto& p = in.point(v);
    mesh.vertices.emplace_back(p[0], p[1], p[2]);
  }
  for (const auto f : in.faces()) {
    Triangle t{};
    int corner = 0;
    for (const auto v : in.fv_range(f)) {
      if (corner < 3) t[corner] = static_cast<Index>(v.idx());
      ++corner;
    }
    if (corner != 3) {
      throw Error(Error::Kind::InvalidGeometry,
                  "OpenMesh face " + std::to_string(f.idx()) + " has " + std::to_string(corner) +
                      " corners; only triangles are accepted");
    }
    mesh.add_triangle(t, 0);
  }
  return mesh;
}

}  // namespace vorocrust
