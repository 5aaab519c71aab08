#include "cells/cell_faces.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <utility>

namespace vorocrust::cells {

std::optional<CellFaces> welded_faces(const RawCell& cell, std::size_t first_instance, const std::vector<Index>& point_of) {
  // Local names for the cell's points: the first of its vertices welded to each, so that the
  // checks below run on small arrays rather than sorted lists.
  const std::size_t n = cell.vertices.size();
  std::vector<std::uint32_t> local(n);
  for (std::size_t v = 0; v < n; ++v) {
    const Index p = point_of[first_instance + v];
    std::size_t u = 0;
    while (point_of[first_instance + u] != p) ++u;
    local[v] = static_cast<std::uint32_t>(u);
  }

  CellFaces out;
  std::vector<std::uint32_t> polygon;
  std::vector<std::uint32_t> stamp(n, UINT32_MAX);
  std::vector<std::uint8_t> edge_uses(n * n, 0);
  for (std::uint32_t f = 0; f < cell.num_faces(); ++f) {
    polygon.clear();
    for (std::uint32_t k = cell.starts[f]; k < cell.starts[f + 1]; ++k) {
      const std::uint32_t v = local[cell.cycles[k]];
      if (polygon.empty() || polygon.back() != v) polygon.push_back(v);
    }
    while (polygon.size() > 1 && polygon.back() == polygon.front()) polygon.pop_back();
    if (polygon.size() < 3) continue;
    for (std::uint32_t v : polygon) {
      if (stamp[v] == f) return std::nullopt;  // the face passes a point twice
      stamp[v] = f;
    }
    for (std::size_t k = 0; k < polygon.size(); ++k) {
      if (++edge_uses[polygon[k] * n + polygon[(k + 1) % polygon.size()]] > 1) return std::nullopt;
    }
    out.neighbours.push_back(cell.neighbours[f]);
    out.starts.push_back(static_cast<std::uint32_t>(out.points.size()));
    for (std::uint32_t v : polygon) out.points.push_back(point_of[first_instance + v]);
  }
  out.starts.push_back(static_cast<std::uint32_t>(out.points.size()));

  // Closed: every directed edge once (checked above), and its reverse once.
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      if (edge_uses[a * n + b] != edge_uses[b * n + a]) return std::nullopt;
    }
  }
  if (out.num_faces() < 4) return std::nullopt;
  return out;
}

std::size_t drop_edge_points(std::vector<CellFaces>& cells, std::size_t num_points) {
  // Per point: 1 when some cell has it, 2 when some cell has it in other than two faces.
  std::vector<std::atomic<std::uint8_t>> use(num_points);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cells.size(), 1024), [&](const auto& range) {
    std::vector<Index> points;
    for (std::size_t c = range.begin(); c != range.end(); ++c) {
      points.assign(cells[c].points.begin(), cells[c].points.end());
      std::sort(points.begin(), points.end());
      for (std::size_t k = 0; k < points.size();) {
        std::size_t run = k;
        while (run < points.size() && points[run] == points[k]) ++run;
        const std::uint8_t mark = run - k == 2 ? 1 : 2;
        std::uint8_t seen = use[points[k]].load(std::memory_order_relaxed);
        while (seen < mark && !use[points[k]].compare_exchange_weak(seen, mark, std::memory_order_relaxed)) {
        }
        k = run;
      }
    }
  });
  std::size_t dropped = 0;
  for (const auto& u : use) dropped += u.load(std::memory_order_relaxed) == 1;
  if (dropped == 0) return 0;
  tbb::parallel_for(std::size_t{0}, cells.size(), [&](std::size_t c) {
    // A face left with fewer than three points spanned no area (a triangle whose corner only
    // split an edge of its neighbour face): dropped, as welding drops such faces, and by both
    // cells beside it alike, as both see the same points.
    CellFaces& cell = cells[c];
    std::size_t kept = 0, kept_faces = 0;
    for (std::size_t f = 0; f < cell.num_faces(); ++f) {
      const std::uint32_t begin = cell.starts[f], end = cell.starts[f + 1];
      const std::size_t first = kept;
      for (std::uint32_t k = begin; k < end; ++k) {
        if (use[cell.points[k]].load(std::memory_order_relaxed) != 1) cell.points[kept++] = cell.points[k];
      }
      if (kept - first < 3) {
        kept = first;
        continue;
      }
      cell.starts[kept_faces] = static_cast<std::uint32_t>(first);
      cell.neighbours[kept_faces++] = cell.neighbours[f];
    }
    cell.neighbours.resize(kept_faces);
    cell.starts.resize(kept_faces + 1);
    cell.starts[kept_faces] = static_cast<std::uint32_t>(kept);
    cell.points.resize(kept);
  });
  return dropped;
}

}  // namespace vorocrust::cells
