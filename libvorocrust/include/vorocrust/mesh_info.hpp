// vorocrust/mesh_info.hpp — counts and measures of an input surface, as `vorocrust info` shows.
//
// Components are sets of faces joined through edges (an edge with three faces joins all three).
// A component is *closed* when none of its edges has one face, *manifold* when none has more
// than two; genus and enclosed volume are given only where both hold.
#pragma once

#include "vorocrust/api.hpp"

#include <Eigen/Geometry>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

struct VOROCRUST_API ComponentInfo {
  std::size_t faces = 0;
  std::size_t vertices = 0;
  std::size_t edges = 0;
  std::size_t boundary_edges = 0;
  std::size_t non_manifold_edges = 0;
  bool closed() const { return boundary_edges == 0; }
  bool manifold() const { return non_manifold_edges == 0; }
  long euler_characteristic() const {  // V - E + F
    return static_cast<long>(vertices) - static_cast<long>(edges) + static_cast<long>(faces);
  }
  std::optional<int> genus;       // closed and manifold only
  std::optional<double> volume;   // signed enclosed volume, closed and manifold only
  double area = 0.0;
};

struct VOROCRUST_API GroupInfo {
  std::string name;
  std::string source_file;
  std::size_t faces = 0;
};

struct VOROCRUST_API MeshInfo {
  std::size_t vertices = 0;
  std::size_t faces = 0;
  std::size_t edges = 0;
  std::size_t boundary_edges = 0;
  std::size_t non_manifold_edges = 0;
  std::vector<ComponentInfo> components;  // largest first
  std::vector<GroupInfo> groups;
  std::optional<int> genus;  // sum over components, when every component is closed and manifold
  Eigen::AlignedBox3d bounding_box;
  double area = 0.0;
};

VOROCRUST_API MeshInfo mesh_info(const SurfaceMesh& mesh);

}  // namespace vorocrust
