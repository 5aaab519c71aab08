#include "cells/cell_faces.hpp"

#include <algorithm>
#include <utility>

namespace vorocrust::cells {

std::optional<CellFaces> welded_faces(const RawCell& cell, std::size_t first_instance, const std::vector<Index>& point_of) {
  CellFaces out;
  std::vector<Index> polygon;
  for (std::size_t f = 0; f < cell.num_faces(); ++f) {
    polygon.clear();
    for (std::uint32_t k = cell.starts[f]; k < cell.starts[f + 1]; ++k) {
      const Index p = point_of[first_instance + cell.cycles[k]];
      if (polygon.empty() || polygon.back() != p) polygon.push_back(p);
    }
    while (polygon.size() > 1 && polygon.back() == polygon.front()) polygon.pop_back();
    if (polygon.size() < 3) continue;
    std::vector<Index> sorted = polygon;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return std::nullopt;
    out.neighbours.push_back(cell.neighbours[f]);
    out.starts.push_back(static_cast<std::uint32_t>(out.points.size()));
    out.points.insert(out.points.end(), polygon.begin(), polygon.end());
  }
  out.starts.push_back(static_cast<std::uint32_t>(out.points.size()));

  // Closed: every directed edge once, and its reverse once.
  std::vector<std::pair<Index, Index>> edges;
  for (std::size_t f = 0; f < out.num_faces(); ++f) {
    for (std::uint32_t k = out.starts[f]; k < out.starts[f + 1]; ++k) {
      const std::uint32_t next = k + 1 == out.starts[f + 1] ? out.starts[f] : k + 1;
      edges.emplace_back(out.points[k], out.points[next]);
    }
  }
  std::sort(edges.begin(), edges.end());
  if (std::adjacent_find(edges.begin(), edges.end()) != edges.end()) return std::nullopt;
  for (const auto& [a, b] : edges) {
    if (!std::binary_search(edges.begin(), edges.end(), std::make_pair(b, a))) return std::nullopt;
  }
  if (out.num_faces() < 4) return std::nullopt;
  return out;
}

}  // namespace vorocrust::cells
