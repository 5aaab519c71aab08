// Voronoi cells in the plane by clipping, and their assembly into one mesh (2D domains).
#include "cells/plane_cells.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "core/union_find.hpp"
#include "geometry/plane_tree.hpp"

namespace vorocrust::cells {

namespace {

// The part of `cell` on seed p's side of the bisector of p and q; the new edge lies across `label`.
void clip(PlanePolygon& cell, const Point2& p, const Point2& q, std::int64_t label, PlanePolygon& scratch) {
  const Point2 n = q - p, m = (p + q) / 2;
  const std::size_t count = cell.vertices.size();
  std::array<double, 64> small;
  std::vector<double> big;
  double* side = small.data();
  if (count > small.size()) {
    big.resize(count);
    side = big.data();
  }
  bool any_out = false;
  for (std::size_t k = 0; k < count; ++k) {
    side[k] = (cell.vertices[k] - m).dot(n);
    any_out |= side[k] > 0;
  }
  if (!any_out) return;
  scratch.vertices.clear();
  scratch.across.clear();
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t next = (k + 1) % count;
    const bool in = side[k] <= 0, next_in = side[next] <= 0;
    if (in) {
      scratch.vertices.push_back(cell.vertices[k]);
      scratch.across.push_back(cell.across[k]);
    }
    if (in == next_in) continue;
    // Leaving, the bisector's edge starts at the exit point; entering, the rest of edge k starts
    // at the entry point. A vertex on the bisector is its own exit (or entry) point.
    if (in && side[k] == 0) {
      scratch.across.back() = label;
      continue;
    }
    if (!in && side[next] == 0) continue;
    const double t = side[k] / (side[k] - side[next]);
    scratch.vertices.push_back(cell.vertices[k] + t * (cell.vertices[next] - cell.vertices[k]));
    scratch.across.push_back(in ? label : cell.across[k]);
  }
  std::swap(cell, scratch);
}

}  // namespace

double polygon_area(const std::vector<Point2>& ring, Point2* centroid) {
  double twice = 0;
  Point2 c = Point2::Zero();
  const Point2 o = ring.empty() ? Point2::Zero() : ring[0];
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Point2 a = ring[k] - o, b = ring[(k + 1) % ring.size()] - o;
    const double cross = a.x() * b.y() - a.y() * b.x();
    twice += cross;
    c += cross * (a + b);
  }
  if (centroid) *centroid = twice != 0 ? Point2(o + c / (3 * twice)) : o;
  return twice / 2;
}

std::vector<PlanePolygon> plane_voronoi_cells(const std::vector<Point2>& seeds, const Eigen::AlignedBox2d& frame) {
  const geometry::PlaneTree tree(seeds);
  std::vector<PlanePolygon> cells(seeds.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, seeds.size(), 256), [&](const tbb::blocked_range<std::size_t>& range) {
    std::vector<std::uint32_t> index;
    std::vector<double> squared;
    PlanePolygon scratch;
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      PlanePolygon& cell = cells[i];
      const Point2 lo = frame.min(), hi = frame.max();
      cell.vertices = {lo, Point2(hi.x(), lo.y()), hi, Point2(lo.x(), hi.y())};
      cell.across = {-1, -2, -3, -4};  // bottom, right, top, left
      const Point2& p = seeds[i];
      std::size_t done = 0;
      for (std::size_t k = 16;; k *= 2) {
        k = std::min(k, seeds.size());
        index.resize(k);
        squared.resize(k);
        const std::size_t found = tree.nearest(p, k, index.data(), squared.data());
        for (std::size_t n = done; n < found; ++n) {
          if (index[n] != i) clip(cell, p, seeds[index[n]], index[n], scratch);
        }
        done = found;
        double reach = 0;
        for (const Point2& v : cell.vertices) reach = std::max(reach, (v - p).squaredNorm());
        // A seed farther than twice the cell's reach cannot cut it.
        if (found == seeds.size() || squared[found - 1] > 4 * reach) break;
      }
    }
  });
  return cells;
}

PlaneAssembly weld_plane_cells(const std::vector<PlanePolygon>& cells, const std::vector<Point2>& seeds,
                               const std::vector<PlaneCircle>& circles,
                               const std::vector<std::array<std::int32_t, 2>>& on_circles, double tolerance) {
  // Every vertex named by its three seeds.
  struct Corner {
    std::array<std::int64_t, 3> key;
    std::uint32_t cell, k;
  };
  std::vector<Corner> corners;
  std::vector<std::size_t> offset(cells.size() + 1, 0);
  for (std::size_t i = 0; i < cells.size(); ++i) offset[i + 1] = offset[i] + cells[i].vertices.size();
  corners.resize(offset.back());
  tbb::parallel_for(std::size_t{0}, cells.size(), [&](std::size_t i) {
    const PlanePolygon& c = cells[i];
    const std::size_t n = c.vertices.size();
    for (std::size_t k = 0; k < n; ++k) {
      std::array<std::int64_t, 3> key{static_cast<std::int64_t>(i), c.across[(k + n - 1) % n], c.across[k]};
      std::sort(key.begin(), key.end());
      corners[offset[i] + k] = {key, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(k)};
    }
  });
  tbb::parallel_sort(corners.begin(), corners.end(), [](const Corner& a, const Corner& b) {
    return std::tie(a.key, a.cell, a.k) < std::tie(b.key, b.cell, b.k);
  });
  std::vector<Index> vertex_of(corners.size());
  std::vector<Point2> points;
  for (std::size_t c = 0; c < corners.size(); ++c) {
    if (c == 0 || corners[c].key != corners[c - 1].key) points.push_back(cells[corners[c].cell].vertices[corners[c].k]);
    vertex_of[offset[corners[c].cell] + corners[c].k] = static_cast<Index>(points.size() - 1);
  }
  // The centres of the circles: the seeds on each make it one vertex, which only the cells of
  // those seeds have.
  for (std::size_t i = 0; i < std::min(cells.size(), on_circles.size()); ++i) {
    const std::size_t n = cells[i].vertices.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Index v = vertex_of[offset[i] + k];
      for (const std::int32_t c : on_circles[i]) {
        if (c < 0) continue;
        const PlaneCircle& circle = circles[static_cast<std::size_t>(c)];
        if ((cells[i].vertices[k] - circle.centre).norm() <= std::max(tolerance, 1e-7 * circle.radius)) points[v] = circle.centre;
      }
    }
  }
  // Points within the tolerance of each other are one (the seeds of a degenerate vertex name it
  // by different triples in different cells), and so are the ends of shorter edges.
  UnionFind same(points.size());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const std::size_t n = cells[i].vertices.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Index a = vertex_of[offset[i] + k], b = vertex_of[offset[i] + (k + 1) % n];
      if ((points[a] - points[b]).norm() <= tolerance) same.unite(a, b);
    }
  }
  // Points by the cell `tolerance` wide that holds them, compared with those of the neighbouring
  // cells (a sweep in x alone goes quadratic along a lattice's columns).
  const auto cell_of = [&](Index v) {
    return std::pair<std::int64_t, std::int64_t>(static_cast<std::int64_t>(std::floor(points[v].x() / tolerance)),
                                                 static_cast<std::int64_t>(std::floor(points[v].y() / tolerance)));
  };
  std::vector<std::pair<std::pair<std::int64_t, std::int64_t>, Index>> by_cell(points.size());
  tbb::parallel_for(std::size_t{0}, points.size(), [&](std::size_t v) { by_cell[v] = {cell_of(static_cast<Index>(v)), static_cast<Index>(v)}; });
  tbb::parallel_sort(by_cell.begin(), by_cell.end());
  // Each pair of neighbouring cells is looked at from its lower one: the same column (this cell
  // and the next, which follow in the order) and the next column (rows j - 1 to j + 1, found by
  // one search).
  const auto near = [&](Index a, Index b) {
    if ((points[a] - points[b]).norm() <= tolerance) same.unite(a, b);
  };
  for (auto k = by_cell.begin(); k != by_cell.end(); ++k) {
    const auto [i, j] = k->first;
    for (auto l = k + 1; l != by_cell.end() && l->first.first == i && l->first.second <= j + 1; ++l) near(k->second, l->second);
    auto l = std::lower_bound(k, by_cell.end(), std::make_pair(std::make_pair(i + 1, j - 1), Index{0}));
    for (; l != by_cell.end() && l->first.first == i + 1 && l->first.second <= j + 1; ++l) near(k->second, l->second);
  }
  PlaneAssembly out;
  std::vector<Index> renumber(points.size(), static_cast<Index>(-1));
  for (Index v = 0; v < points.size(); ++v) {
    const Index r = static_cast<Index>(same.find(v));
    if (renumber[r] == static_cast<Index>(-1)) {
      renumber[r] = static_cast<Index>(out.points.size());
      out.points.push_back(points[r]);
    }
    renumber[v] = renumber[r];
  }
  out.polygons.resize(cells.size());
  out.across.resize(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const std::size_t n = cells[i].vertices.size();
    std::vector<Index>& ring = out.polygons[i];
    std::vector<std::int64_t>& across = out.across[i];
    for (std::size_t k = 0; k < n; ++k) {
      const Index a = renumber[vertex_of[offset[i] + k]], b = renumber[vertex_of[offset[i] + (k + 1) % n]];
      if (a == b) continue;  // a collapsed edge
      ring.push_back(a);
      across.push_back(cells[i].across[k]);
    }
  }
  // Each edge between two cells is the same in both, run the other way.
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (out.polygons[i].size() < 3) {
      throw Error(Error::Kind::InvalidGeometry, "the cell of seed " + std::to_string(i) + " at (" + std::to_string(seeds[i].x()) + ", " +
                                                    std::to_string(seeds[i].y()) + ") collapses when its vertices are welded");
    }
  }
  std::atomic<std::int64_t> disagreeing{-1};
  tbb::parallel_for(std::size_t{0}, cells.size(), [&](std::size_t i) {
    const std::vector<Index>& ring = out.polygons[i];
    const std::size_t n = ring.size();
    for (std::size_t k = 0; k < n; ++k) {
      const std::int64_t j = out.across[i][k];
      if (j < 0) continue;
      const std::vector<Index>& other = out.polygons[static_cast<std::size_t>(j)];
      const std::size_t m = other.size();
      bool found = false;
      for (std::size_t e = 0; e < m && !found; ++e) {
        found = other[e] == ring[(k + 1) % n] && other[(e + 1) % m] == ring[k] &&
                out.across[static_cast<std::size_t>(j)][e] == static_cast<std::int64_t>(i);
      }
      if (found) continue;
      // The lowest such cell is named, whichever thread finds it.
      std::int64_t seen = disagreeing.load();
      while ((seen < 0 || static_cast<std::int64_t>(i) < seen) && !disagreeing.compare_exchange_weak(seen, static_cast<std::int64_t>(i))) {
      }
    }
  });
  if (const std::int64_t i = disagreeing; i >= 0) {
    throw Error(Error::Kind::InvalidGeometry, "the cell of seed " + std::to_string(i) + " at (" + std::to_string(seeds[static_cast<std::size_t>(i)].x()) + ", " +
                                                  std::to_string(seeds[static_cast<std::size_t>(i)].y()) +
                                                  ") and a neighbour disagree on the edge between them after welding");
  }
  return out;
}

}  // namespace vorocrust::cells
