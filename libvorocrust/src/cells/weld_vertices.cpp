#include "cells/weld_vertices.hpp"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <utility>

#include "core/union_find.hpp"

namespace vorocrust::cells {

double weld_tolerance(const Point& vertex, const Point& seed, double relative) {
  return relative * std::max((vertex - seed).norm(), 1.0);
}

namespace {

// Unites each vertex of cell c's face toward cell d with its nearest counterpart on d's face
// toward c, when they are within tolerance.
void unite_across_faces(const std::vector<RawCell>& cells, const std::vector<Index>& cell_seeds,
                        const std::vector<std::int32_t>& cell_of_seed, const Frame& frame,
                        const std::vector<std::size_t>& first, const std::vector<double>& relative_of_cell,
                        UnionFind& sets, std::size_t c) {
  const RawCell& cell = cells[c];
  const Point& seed = frame.normalized[cell_seeds[c]];
  for (std::size_t f = 0; f < cell.num_faces(); ++f) {
    const std::int32_t n = cell.neighbours[f];
    if (n < 0 || cell_of_seed[static_cast<std::size_t>(n)] <= static_cast<std::int32_t>(c)) continue;
    const auto d = static_cast<std::size_t>(cell_of_seed[static_cast<std::size_t>(n)]);
    const RawCell& other = cells[d];
    const double relative = std::max(relative_of_cell[c], relative_of_cell[d]);
    const auto it = std::find(other.neighbours.begin(), other.neighbours.end(), static_cast<std::int32_t>(cell_seeds[c]));
    if (it == other.neighbours.end()) continue;  // a face only one side sees: degenerate, left to the sweep
    const auto g = static_cast<std::size_t>(it - other.neighbours.begin());
    const std::uint32_t* mine = cell.cycles.data() + cell.starts[f];
    const std::uint32_t* theirs = other.cycles.data() + other.starts[g];
    const std::size_t size = cell.starts[f + 1] - cell.starts[f], other_size = other.starts[g + 1] - other.starts[g];
    const auto unite = [&](std::uint32_t u, std::uint32_t w) {
      sets.unite(static_cast<std::uint32_t>(first[c] + u), static_cast<std::uint32_t>(first[d] + w));
    };
    // As a rule the two cycles are the same points run in opposite directions: pair them off
    // from the counterpart of the first, checking each pair.
    if (size == other_size) {
      const Point& u0 = cell.vertices[mine[0]];
      std::size_t at = 0;
      for (std::size_t m = 1; m < size; ++m) {
        if ((other.vertices[theirs[m]] - u0).squaredNorm() < (other.vertices[theirs[at]] - u0).squaredNorm()) at = m;
      }
      bool paired = true;
      for (std::size_t k = 0; k < size && paired; ++k) {
        const Point& u = cell.vertices[mine[k]];
        paired = (other.vertices[theirs[(at + size - k) % size]] - u).norm() <= weld_tolerance(u, seed, relative);
      }
      if (paired) {
        for (std::size_t k = 0; k < size; ++k) unite(mine[k], theirs[(at + size - k) % size]);
        continue;
      }
    }
    // Otherwise (a degenerate vertex resolved differently on each side) each to its nearest.
    for (std::size_t k = 0; k < size; ++k) {
      const Point& u = cell.vertices[mine[k]];
      double best = weld_tolerance(u, seed, relative);
      std::uint32_t match = UINT32_MAX;
      for (std::size_t m = 0; m < other_size; ++m) {
        const double dist = (other.vertices[theirs[m]] - u).norm();
        if (dist <= best) best = dist, match = theirs[m];
      }
      if (match != UINT32_MAX) unite(mine[k], match);
    }
  }
}

// Unites in `sets` every two points within the larger of their tolerances of each other: sorted
// by x, each is compared with those following it within the largest tolerance.
void unite_close_points(const std::vector<Point>& position, const std::vector<double>& tol, UnionFind& sets) {
  // Sorted as (x, index) pairs by value: a comparison that looks the points up scatters over
  // millions of them and took a tenth of the cells stage.
  std::vector<std::pair<double, std::uint32_t>> roots(position.size());
  for (std::uint32_t i = 0; i < position.size(); ++i) roots[i] = {position[i].x(), i};
  tbb::parallel_sort(roots.begin(), roots.end());
  double reach = 0;
  for (const auto& [x, r] : roots) reach = std::max(reach, tol[r]);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, roots.size(), 4096), [&](const auto& range) {
    for (std::size_t k = range.begin(); k < range.end(); ++k) {
      const auto [x, a] = roots[k];
      for (std::size_t j = k + 1; j < roots.size() && roots[j].first - x <= reach; ++j) {
        const std::uint32_t b = roots[j].second;
        if ((position[a] - position[b]).norm() <= std::max(tol[a], tol[b])) sets.unite(a, b);
      }
    }
  });
}

// The point equidistant from `generators` (least squares beyond four), or `fallback` when they
// do not pin it down within `limit`.
Point circumcentre(const Index* generators, std::size_t count, const std::vector<Point>& seeds, const Point& fallback,
                   double limit) {
  if (count < 4) return fallback;
  const Point& g0 = seeds[generators[0]];
  Point x;
  if (count == 4) {
    const Point a = seeds[generators[1]] - g0, b = seeds[generators[2]] - g0, c = seeds[generators[3]] - g0;
    const Point bc = b.cross(c), ca = c.cross(a), ab = a.cross(b);
    x = (a.squaredNorm() * bc + b.squaredNorm() * ca + c.squaredNorm() * ab) / (2 * a.dot(bc));
  } else {
    Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    for (std::size_t k = 1; k < count; ++k) {
      const Eigen::Vector3d a = seeds[generators[k]] - g0;
      normal += a * a.transpose();
      rhs += 0.5 * a.squaredNorm() * a;
    }
    x = normal.ldlt().solve(rhs);
  }
  const Point p = g0 + x;
  return p.allFinite() && (p - fallback).norm() <= limit ? p : fallback;
}

// Raw vertices a little more than the tolerance apart about nearly cospherical seeds (a corner
// ball's centre) are distinct points, yet their circumcentres fit the same seeds and can land
// within round-off of each other, which would leave faces of no area (checkMesh: "incorrectly
// oriented"). Placed points within tolerance of each other become one as well, the lowest.
// `point_tol`: per point, its tolerance.
void merge_coincident_points(WeldedVertices& w, const std::vector<double>& point_tol, const Frame& frame) {
  const std::size_t n = w.points.size();
  std::vector<Point> placed(n);
  for (std::size_t p = 0; p < n; ++p) placed[p] = (w.points[p] - frame.centre) / frame.scale;
  UnionFind sets(n);
  unite_close_points(placed, point_tol, sets);
  std::vector<Index> label(n, 0);
  Index kept = 0;
  for (std::uint32_t p = 0; p < n; ++p) {
    const std::uint32_t r = sets.find(p);
    label[p] = r == p ? kept++ : label[r];
  }
  if (kept == n) return;
  std::vector<Point> points(kept);
  for (std::uint32_t p = 0; p < n; ++p) {
    if (sets.find(p) == p) points[label[p]] = w.points[p];
  }
  w.points = std::move(points);
  for (Index& p : w.point_of) p = label[p];
}

}  // namespace

WeldedVertices weld_vertices(const std::vector<RawCell>& cells, const std::vector<Index>& cell_seeds,
                             const std::vector<std::int32_t>& cell_of_seed, const Frame& frame,
                             const std::vector<double>& relative_tolerance) {
  WeldedVertices w;
  w.first_instance.resize(cells.size() + 1, 0);
  for (std::size_t c = 0; c < cells.size(); ++c) w.first_instance[c + 1] = w.first_instance[c] + cells[c].vertices.size();
  const std::size_t instances = w.first_instance.back();

  UnionFind sets(instances);
  tbb::parallel_for(std::size_t{0}, cells.size(), [&](std::size_t c) {
    unite_across_faces(cells, cell_seeds, cell_of_seed, frame, w.first_instance, relative_tolerance, sets, c);
  });
  // The instances still apart (their set's root, its lowest), in order: their positions and
  // tolerances, and the sweep's unions among them. Only these: the arrays of every instance were
  // four times as long, and filling them cost page faults on every run.
  std::vector<std::uint32_t> apart;
  std::vector<Point> position;
  std::vector<double> tol;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const Point& seed = frame.normalized[cell_seeds[c]];
    for (std::size_t v = 0; v < cells[c].vertices.size(); ++v) {
      const auto i = static_cast<std::uint32_t>(w.first_instance[c] + v);
      if (sets.find(i) != i) continue;
      apart.push_back(i);
      position.push_back(cells[c].vertices[v]);
      tol.push_back(weld_tolerance(cells[c].vertices[v], seed, relative_tolerance[c]));
    }
  }
  UnionFind close(apart.size());
  unite_close_points(position, tol, close);
  for (std::uint32_t k = 0; k < apart.size(); ++k) sets.unite(apart[k], apart[close.find(k)]);

  // Points numbered by their first instance, which is their set's root.
  std::vector<std::uint32_t> root(instances);
  tbb::parallel_for(std::size_t{0}, instances, [&](std::size_t i) { root[i] = sets.find(static_cast<std::uint32_t>(i)); });
  // A root lies among those apart (an instance united with a lower one across a face is none).
  std::vector<Index> label(instances, 0);
  std::vector<double> point_tol;  // per point, its root's tolerance
  Index points = 0;
  for (std::size_t k = 0; k < apart.size(); ++k) {
    if (root[apart[k]] != apart[k]) continue;
    label[apart[k]] = points++;
    point_tol.push_back(tol[k]);
  }
  w.point_of.resize(instances);
  tbb::parallel_for(std::size_t{0}, instances, [&](std::size_t i) { w.point_of[i] = label[root[i]]; });

  w.points.resize(points);
  tbb::parallel_for(std::size_t{0}, cells.size(), [&](std::size_t c) {
    const RawCell& cell = cells[c];
    // The seeds around each vertex: the cell's own, then those across the faces at it.
    const std::size_t n = cell.vertices.size();
    std::vector<std::uint32_t> start(n + 2, 0);
    for (std::uint32_t v : cell.cycles) ++start[v + 2];
    for (std::size_t v = 0; v < n; ++v) start[v + 2] += start[v + 1] + 1;
    std::vector<Index> around(cell.cycles.size() + n);
    for (std::size_t v = 0; v < n; ++v) around[start[v + 1]++] = cell_seeds[c];
    for (std::size_t f = 0; f < cell.num_faces(); ++f) {
      for (std::uint32_t k = cell.starts[f]; k < cell.starts[f + 1]; ++k) {
        around[start[cell.cycles[k] + 1]++] = static_cast<Index>(cell.neighbours[f]);
      }
    }
    for (std::size_t v = 0; v < n; ++v) {
      const std::size_t i = w.first_instance[c] + v;
      if (root[i] != i) continue;
      const Point at = frame.centre + frame.scale * cell.vertices[v];
      w.points[label[i]] = circumcentre(around.data() + start[v], start[v + 1] - start[v], frame.original, at,
                                        10 * point_tol[label[i]] * frame.scale);
    }
  });
  merge_coincident_points(w, point_tol, frame);
  return w;
}

}  // namespace vorocrust::cells
