#include "core/edge_topology.hpp"

#include <algorithm>
#include <numeric>

namespace vorocrust {

EdgeTopology build_edge_topology(const SurfaceMesh& mesh) {
  struct Corner {
    Index a, b, face;
    std::uint8_t slot;
  };
  // The corners ordered by (a, b, face, slot): placed by their smaller vertex a (a counting sort,
  // in face and slot order), then each vertex's few by b, stably. Sorting them all at once cost
  // the smoothing of igl_bunny a third of its time, as every round builds the topology afresh.
  // A mesh with an index past its vertices (not yet validated) is sorted whole instead, rather
  // than sizing the count by that index.
  Index top = 0;
  for (const Triangle& t : mesh.triangles) top = std::max({top, t[0], t[1], t[2]});
  std::vector<Corner> corners(3 * mesh.triangles.size());
  const auto corner = [&](std::size_t f, std::uint8_t k) {
    const Index u = mesh.triangles[f][k], v = mesh.triangles[f][(k + 1) % 3];
    return Corner{std::min(u, v), std::max(u, v), static_cast<Index>(f), k};
  };
  if (std::size_t{top} >= mesh.vertices.size()) {
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
      for (std::uint8_t k = 0; k < 3; ++k) corners[3 * f + k] = corner(f, k);
    }
    std::sort(corners.begin(), corners.end(), [](const Corner& x, const Corner& y) {
      return std::tie(x.a, x.b, x.face, x.slot) < std::tie(y.a, y.b, y.face, y.slot);
    });
  } else {
    std::vector<std::size_t> start(mesh.vertices.size() + 1, 0);
    for (const Triangle& t : mesh.triangles) {
      for (int k = 0; k < 3; ++k) ++start[std::size_t{std::min(t[k], t[(k + 1) % 3])} + 1];
    }
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
      for (std::uint8_t k = 0; k < 3; ++k) {
        const Corner c = corner(f, k);
        corners[fill[c.a]++] = c;
      }
    }
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
      const auto first = corners.begin() + static_cast<std::ptrdiff_t>(start[v]);
      const auto last = corners.begin() + static_cast<std::ptrdiff_t>(start[v + 1]);
      if (last - first < 2) continue;
      if (last - first > 32) {
        std::stable_sort(first, last, [](const Corner& x, const Corner& y) { return x.b < y.b; });
        continue;
      }
      for (auto i = first + 1; i < last; ++i) {  // insertion sort: stable, and fast on so few
        const Corner c = *i;
        auto j = i;
        for (; j > first && c.b < (j - 1)->b; --j) *j = *(j - 1);
        *j = c;
      }
    }
  }
  EdgeTopology topo;
  topo.face_edges.resize(mesh.triangles.size());
  topo.edge_faces.reserve(corners.size());
  for (std::size_t i = 0; i < corners.size();) {
    const Index e = static_cast<Index>(topo.edges.size());
    topo.edges.push_back({corners[i].a, corners[i].b});
    topo.face_offsets.push_back(topo.edge_faces.size());
    for (; i < corners.size() && corners[i].a == topo.edges.back()[0] && corners[i].b == topo.edges.back()[1]; ++i) {
      topo.edge_faces.push_back(corners[i].face);
      topo.face_edges[corners[i].face][corners[i].slot] = e;
    }
  }
  topo.face_offsets.push_back(topo.edge_faces.size());
  return topo;
}

int edge_direction(const Triangle& face, Index a, Index b) {
  for (int k = 0; k < 3; ++k) {
    if (face[k] == a && face[(k + 1) % 3] == b) return 1;
    if (face[k] == b && face[(k + 1) % 3] == a) return -1;
  }
  return 0;
}

}  // namespace vorocrust
