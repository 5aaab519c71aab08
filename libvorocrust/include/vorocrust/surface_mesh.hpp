// vorocrust/surface_mesh.hpp — the input model: a triangle soup that keeps every face.
//
// A SurfaceMesh is deliberately not a halfedge structure: input surfaces may have edges shared
// by three or more faces (interfaces between materials), open boundaries and many components,
// and all of them must survive loading. Connectivity is derived on demand (see mesh_info.hpp).
//
// Region labels: a triangle's *front* is the side its normal (right-hand rule over the vertex
// order) points to, its *back* the other side. When the input names the regions on both sides,
// `face_regions[f]` holds their indices into `region_names`; otherwise `face_regions` is empty.
#pragma once

#include "vorocrust/api.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products on Point
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace vorocrust {

using Index = std::uint32_t;
using Point = Eigen::Vector3d;
using Triangle = std::array<Index, 3>;

// The two regions a triangle separates; kUnknownRegion where the input does not say.
struct VOROCRUST_API RegionPair {
  static constexpr std::int32_t kUnknownRegion = -1;
  std::int32_t back = kUnknownRegion;
  std::int32_t front = kUnknownRegion;
  friend bool operator==(const RegionPair&, const RegionPair&) = default;
};

// A named set of faces: an OBJ `o`/`g` group, an STL solid, or a whole input file.
struct VOROCRUST_API FaceGroup {
  std::string name;
  std::string source_file;  // the file the group was read from
};

struct VOROCRUST_API SurfaceMesh {
  std::vector<Point> vertices;
  std::vector<Triangle> triangles;
  std::vector<Index> face_group;  // one per triangle, index into `groups`
  std::vector<FaceGroup> groups;
  // 1-based line of each triangle in its source file, 0 where unknown (binary formats).
  std::vector<std::uint32_t> face_line;
  std::vector<RegionPair> face_regions;  // empty, or one per triangle
  // Where triangles were made from others (smoothing subdivides faces, resolving self-intersections
  // cuts them): the face of the model as read that each came from, which messages name with its
  // line. Empty: each triangle is a face as read.
  std::vector<Index> face_source;
  std::vector<std::string> region_names;

  std::size_t num_vertices() const { return vertices.size(); }
  std::size_t num_faces() const { return triangles.size(); }
  bool has_regions() const { return !face_regions.empty(); }
  Index source_face(std::size_t face) const {
    return face < face_source.size() ? face_source[face] : static_cast<Index>(face);
  }

  // Appends a triangle with its group and source line, keeping the per-face arrays aligned.
  void add_triangle(const Triangle& t, Index group, std::uint32_t line = 0);
  // Reverses a triangle's orientation, swapping its region pair with it.
  void flip(std::size_t face);
};

// Where a face came from, "bunny.off line 12 (face 7)", for messages.
VOROCRUST_API std::string describe_face(const SurfaceMesh& mesh, std::size_t face);

// A point as messages give it, "(0.1, -2, 3.25)", to 9 significant digits.
VOROCRUST_API std::string describe_point(const Point& p);

}  // namespace vorocrust
