#include "cells/raw_cell_extract.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

namespace vorocrust::cells {
namespace {


// Voro++ numbers a cell's vertices and faces in the order its cuts met them, and a cut that
// changes nothing can still move where the next one starts. Numbered by position (vertices
// lexicographically, faces by the seed across them, each cycle from its lowest vertex), a cell is
// the same whichever seeds were cut in vain, so cells cut again after seeds were added match
// cells cut among all of them.
void canonicalize(RawCell& cell, Scratch& scratch) {
  const std::size_t n = cell.vertices.size();
  std::vector<std::uint32_t>& order = scratch.order;
  order.resize(n);
  std::iota(order.begin(), order.end(), 0u);
  const auto less = [&](std::uint32_t a, std::uint32_t b) {
    const Point &p = cell.vertices[a], &q = cell.vertices[b];
    return std::tie(p.x(), p.y(), p.z(), a) < std::tie(q.x(), q.y(), q.z(), b);
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<std::uint32_t>& rank = scratch.rank;
  rank.resize(n);
  for (std::uint32_t k = 0; k < n; ++k) rank[order[k]] = k;
  std::vector<Point> vertices(n);
  for (std::uint32_t k = 0; k < n; ++k) vertices[k] = cell.vertices[order[k]];
  cell.vertices.swap(vertices);

  const std::size_t faces = cell.neighbours.size();
  std::vector<std::uint32_t>& by_neighbour = scratch.faces_order;
  by_neighbour.resize(faces);
  std::iota(by_neighbour.begin(), by_neighbour.end(), 0u);
  std::sort(by_neighbour.begin(), by_neighbour.end(), [&](std::uint32_t a, std::uint32_t b) {
    return std::tie(cell.neighbours[a], a) < std::tie(cell.neighbours[b], b);
  });
  std::vector<std::int32_t> neighbours(faces);
  std::vector<std::uint32_t> starts, cycles;
  starts.reserve(faces + 1);
  cycles.reserve(cell.cycles.size());
  for (std::size_t k = 0; k < faces; ++k) {
    const std::uint32_t f = by_neighbour[k];
    neighbours[k] = cell.neighbours[f];
    starts.push_back(static_cast<std::uint32_t>(cycles.size()));
    const std::uint32_t begin = cell.starts[f], size = cell.starts[f + 1] - begin;
    std::uint32_t first = 0;
    for (std::uint32_t j = 1; j < size; ++j) {
      if (rank[cell.cycles[begin + j]] < rank[cell.cycles[begin + first]]) first = j;
    }
    for (std::uint32_t j = 0; j < size; ++j) cycles.push_back(rank[cell.cycles[begin + (first + j) % size]]);
  }
  starts.push_back(static_cast<std::uint32_t>(cycles.size()));
  cell.neighbours.swap(neighbours);
  cell.starts.swap(starts);
  cell.cycles.swap(cycles);
}

}  // namespace

bool edges_consistent(const voro::voronoicell_base& cell) {
  if (cell.p < 4) return false;
  for (int i = 0; i < cell.p; ++i) {
    const int order = cell.nu[i];
    if (order < 3 || cell.ed[i] == nullptr) return false;
    for (int j = 0; j < order; ++j) {
      const int k = cell.ed[i][j], back = cell.ed[i][order + j];
      if (k < 0 || k >= cell.p || back < 0 || back >= cell.nu[k] || cell.ed[k][back] != i ||
          cell.ed[k][cell.nu[k] + back] != j) {
        return false;
      }
    }
  }
  return true;
}

bool extract(voro::voronoicell_neighbor& voro_cell, const Point& p, RawCell& cell, Scratch& scratch, double scale) {
  if (!edges_consistent(voro_cell)) return false;
  voro_cell.vertices(0, 0, 0, scratch.xyz);
  for (std::size_t k = 0; k < scratch.xyz.size(); ++k) scratch.xyz[k] = p[static_cast<Eigen::Index>(k % 3)] + scale * scratch.xyz[k];
  voro_cell.face_vertices(scratch.faces);
  voro_cell.neighbors(scratch.ids);
  const std::vector<double>& xyz = scratch.xyz;
  const std::vector<int>& faces = scratch.faces;
  cell.vertices.resize(xyz.size() / 3);
  for (std::size_t v = 0; v < cell.vertices.size(); ++v) cell.vertices[v] = {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]};
  cell.neighbours.assign(scratch.ids.begin(), scratch.ids.end());
  cell.starts.clear();
  cell.cycles.clear();
  // Voro++ lists each face clockwise seen from outside: reverse it.
  for (std::size_t at = 0; at < faces.size(); at += static_cast<std::size_t>(faces[at]) + 1) {
    cell.starts.push_back(static_cast<std::uint32_t>(cell.cycles.size()));
    for (int k = faces[at]; k >= 1; --k) cell.cycles.push_back(static_cast<std::uint32_t>(faces[at + static_cast<std::size_t>(k)]));
  }
  cell.starts.push_back(static_cast<std::uint32_t>(cell.cycles.size()));
  canonicalize(cell, scratch);
  // Each edge is seen from both its faces; from the one where it runs from its lower vertex.
  cell.shortest_edge2 = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < cell.num_faces(); ++f) {
    const std::uint32_t begin = cell.starts[f], end = cell.starts[f + 1];
    for (std::uint32_t k = begin; k < end; ++k) {
      const std::uint32_t a = cell.cycles[k], b = cell.cycles[k + 1 < end ? k + 1 : begin];
      if (a > b) continue;
      const Point &u = cell.vertices[a], &w = cell.vertices[b];
      const double unit2 = std::max({(u - p).squaredNorm(), (w - p).squaredNorm(), 1.0});
      cell.shortest_edge2 = std::min(cell.shortest_edge2, (u - w).squaredNorm() / unit2);
    }
  }
  return true;
}

}  // namespace vorocrust::cells
