// vorocrust/vcg.hpp — SurfaceMesh <-> vcglib triangle meshes, for programs that hold vcglib meshes
// (MeshLab's CMeshO among them; the MeshLab plugin converts its layers with these).
//
// Header-only, so libvorocrust itself does not tie its users to vcglib; include it after vcglib's
// own headers are reachable. MeshType is any vcg::tri::TriMesh with vertex coordinates and faces
// holding vertex pointers.
//
// from_vcg(mesh, name, source, split_selection, what) keeps every live face as it is: faces around non-manifold edges,
// open boundaries and separate components all survive; deleted faces and vertices are skipped,
// and the live vertices keep their order (a mesh without deleted vertices keeps its numbering).
// Coordinates are widened exactly to double. Faces go into the group `name`, or, with
// `split_selection`, the selected ones into the group "NAME/selected" (a group is made only when
// it has faces); each group's source_file is `source`, so messages about faces name it. Throws
// Error(InvalidGeometry) naming the mesh as `what` says (default: "NAME" in quotes) when it has no
// live face, a live vertex has a NaN or infinite coordinate, or a face uses a deleted vertex.
//
// to_vcg(surface, mesh) replaces mesh's contents with the surface's vertices and faces, in order,
// rounded to MeshType's scalar.
#pragma once

#include <vcg/complex/complex.h>

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "vorocrust/error.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

template <class MeshType>
SurfaceMesh from_vcg(const MeshType& mesh, const std::string& name, const std::string& source,
                     bool split_selection = false, std::string what = {}) {
  if (what.empty()) what = "\"" + name + "\"";
  const auto fail = [&](const std::string& why) {
    throw Error(Error::Kind::InvalidGeometry, why, {.file = source});
  };
  if (mesh.fn == 0) fail(what + " has no faces: VoroCrust meshes the volume a triangle surface bounds");
  SurfaceMesh surface;
  constexpr Index kNone = std::numeric_limits<Index>::max();
  std::vector<Index> index(mesh.vert.size(), kNone);
  for (std::size_t v = 0; v < mesh.vert.size(); ++v) {
    if (mesh.vert[v].IsD()) continue;
    const auto& p = mesh.vert[v].cP();
    const Point c{static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2])};
    if (!c.allFinite()) fail("vertex " + std::to_string(v) + " of " + what + " has a NaN or infinite coordinate");
    index[v] = static_cast<Index>(surface.vertices.size());
    surface.vertices.push_back(c);
  }
  std::optional<Index> group[2];  // per selection state, made on first use
  const auto group_of = [&](bool selected) {
    selected = selected && split_selection;
    if (!group[selected]) {
      group[selected] = static_cast<Index>(surface.groups.size());
      surface.groups.push_back({selected ? name + "/selected" : name, source});
    }
    return *group[selected];
  };
  for (std::size_t f = 0; f < mesh.face.size(); ++f) {
    const auto& face = mesh.face[f];
    if (face.IsD()) continue;
    Triangle t{};
    for (int k = 0; k < 3; ++k) {
      t[k] = index[vcg::tri::Index(mesh, face.cV(k))];
      if (t[k] == kNone) fail("face " + std::to_string(f) + " of " + what + " uses a deleted vertex");
    }
    surface.add_triangle(t, group_of(face.IsS()));
  }
  return surface;
}

template <class MeshType>
void to_vcg(const SurfaceMesh& surface, MeshType& mesh) {
  using Scalar = typename MeshType::ScalarType;
  mesh.Clear();
  auto v = vcg::tri::Allocator<MeshType>::AddVertices(mesh, surface.vertices.size());
  for (const Point& p : surface.vertices) {
    v->P() = typename MeshType::CoordType(Scalar(p.x()), Scalar(p.y()), Scalar(p.z()));
    ++v;
  }
  auto f = vcg::tri::Allocator<MeshType>::AddFaces(mesh, surface.triangles.size());
  for (const Triangle& t : surface.triangles) {
    for (int k = 0; k < 3; ++k) f->V(k) = &mesh.vert[t[k]];
    ++f;
  }
}

}  // namespace vorocrust
