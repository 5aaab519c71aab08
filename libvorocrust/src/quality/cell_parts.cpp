// Short edges, tiny faces and dihedral angles (the paper's named limitation, Ebeida and
// Mitchell's reason to weld): each cell's parts against its own size, by layer.
#include "quality/cell_parts.hpp"

#include "quality/histogram_count.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <tuple>
#include <utility>

namespace vorocrust {

double PartDistribution::percent_below(std::size_t k) const {
  return count > 0 ? 100.0 * static_cast<double>(below.at(k)) / static_cast<double>(count) : 0.0;
}

namespace quality {
namespace {

constexpr std::size_t kBlock = 2048;  // cells summed together before the blocks are added in order

PartDistribution empty_distribution(double low, double high, std::size_t bins, std::vector<double> thresholds) {
  PartDistribution d;
  d.low = low;
  d.high = high;
  d.histogram.assign(bins, 0);
  d.below.assign(thresholds.size(), 0);
  d.thresholds = std::move(thresholds);
  return d;
}

// No parts counted yet; the layer keeps its name.
void clear(LayerParts& layer) {
  layer.cells = 0;
  layer.edge_length = empty_distribution(0, 2, 40, {0.01, 0.05, 0.1});
  layer.face_area = empty_distribution(0, 2, 40, {1e-4, 1e-3, 1e-2});
  layer.dihedral_angle = empty_distribution(0, 180, 18, {10, 20});
}

LayerParts empty_layer() {
  LayerParts layer;
  clear(layer);
  return layer;
}

// While summing, `mean` holds the sum.
void add(PartDistribution& d, double value, std::size_t cell) {
  if (d.count == 0 || value < d.min) d.min = value, d.min_cell = cell;
  if (d.count == 0 || value > d.max) d.max = value;
  d.mean += value;
  ++d.count;
  count_in_histogram(value, d.low, d.high, d.histogram, d.above_high);
  for (std::size_t k = 0; k < d.thresholds.size(); ++k) d.below[k] += value < d.thresholds[k];
}

void merge(PartDistribution& into, const PartDistribution& from) {
  if (from.count == 0) return;
  if (into.count == 0 || from.min < into.min) into.min = from.min, into.min_cell = from.min_cell;
  if (into.count == 0 || from.max > into.max) into.max = from.max;
  into.mean += from.mean;
  into.count += from.count;
  into.above_high += from.above_high;
  for (std::size_t k = 0; k < into.histogram.size(); ++k) into.histogram[k] += from.histogram[k];
  for (std::size_t k = 0; k < into.below.size(); ++k) into.below[k] += from.below[k];
}

void merge(LayerParts& into, const LayerParts& from) {
  into.cells += from.cells;
  merge(into.edge_length, from.edge_length);
  merge(into.face_area, from.face_area);
  merge(into.dihedral_angle, from.dihedral_angle);
}

void finish(PartDistribution& d) {
  if (d.count == 0) {
    d.min = d.max = d.mean = 0;
  } else {
    d.mean /= static_cast<double>(d.count);
  }
}

bool in_boundary_layer(const VoronoiMesh& mesh, std::size_t c) {
  const VoronoiCell& cell = mesh.cells[c];
  if (cell.seed_kind == SeedKind::Surface || cell.seed_kind == SeedKind::Cap || cell.seed_kind == SeedKind::Repair) {
    return true;
  }
  for (Index f : cell.faces) {
    const VoronoiFace& face = mesh.faces[f];
    const std::int32_t other = static_cast<std::size_t>(face.owner) == c ? face.neighbour : face.owner;
    if (other == kNoCell || mesh.cells[other].region != cell.region) return true;
  }
  return false;
}

struct CellEdge {
  Index low = 0, high = 0;  // its points, the lower index first
  std::size_t face = 0;     // into the cell's face list
};

void measure_cell(const VoronoiMesh& mesh, std::size_t c, LayerParts& layer, std::vector<CellEdge>& edges,
                  std::vector<Point>& normals) {
  const VoronoiCell& cell = mesh.cells[c];
  const double size = std::cbrt(std::max(cell.volume, 0.0));
  const auto relative = [&](double x, double scale) { return scale > 0 ? x / scale : 0.0; };
  ++layer.cells;
  edges.clear();
  normals.clear();
  for (std::size_t i = 0; i < cell.faces.size(); ++i) {
    const Index f = cell.faces[i];
    const FaceGeometry g = face_geometry(mesh, f);
    add(layer.face_area, relative(g.area, size * size), c);
    normals.push_back(static_cast<std::size_t>(mesh.faces[f].owner) == c ? g.normal : Point(-g.normal));
    const std::vector<Index>& polygon = mesh.faces[f].points;
    for (std::size_t k = 0; k < polygon.size(); ++k) {
      const Index a = polygon[k], b = polygon[(k + 1) % polygon.size()];
      if (a != b) edges.push_back({std::min(a, b), std::max(a, b), i});
    }
  }
  std::sort(edges.begin(), edges.end(), [](const CellEdge& x, const CellEdge& y) {
    return std::tie(x.low, x.high, x.face) < std::tie(y.low, y.high, y.face);
  });
  for (std::size_t k = 0; k < edges.size();) {
    std::size_t end = k + 1;
    while (end < edges.size() && edges[end].low == edges[k].low && edges[end].high == edges[k].high) ++end;
    add(layer.edge_length, relative((mesh.points[edges[k].high] - mesh.points[edges[k].low]).norm(), size), c);
    // A closed cell has each edge in two of its faces; a face without area has no normal.
    const Point &n1 = normals[edges[k].face], &n2 = normals[edges[k + 1 < end ? k + 1 : k].face];
    if (end == k + 2 && n1.squaredNorm() > 0 && n2.squaredNorm() > 0) {
      add(layer.dihedral_angle, std::acos(std::clamp(-n1.dot(n2), -1.0, 1.0)) * 180 / std::numbers::pi, c);
    }
    k = end;
  }
}

}  // namespace

void measure_cell_parts(const VoronoiMesh& mesh, tbb::task_arena& arena, CellQuality& q) {
  const std::size_t blocks = (mesh.cells.size() + kBlock - 1) / kBlock;
  struct BlockSums {
    LayerParts boundary_layer = empty_layer(), interior = empty_layer();
  };
  std::vector<BlockSums> sums(blocks);
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
      std::vector<CellEdge> edges;
      std::vector<Point> normals;
      const std::size_t end = std::min(mesh.cells.size(), (b + 1) * kBlock);
      for (std::size_t c = b * kBlock; c < end; ++c) {
        measure_cell(mesh, c, in_boundary_layer(mesh, c) ? sums[b].boundary_layer : sums[b].interior, edges, normals);
      }
    });
  });
  clear(q.boundary_layer);
  clear(q.interior);
  for (const BlockSums& s : sums) {
    merge(q.boundary_layer, s.boundary_layer);
    merge(q.interior, s.interior);
  }
  for (LayerParts* layer : {&q.boundary_layer, &q.interior}) {
    finish(layer->edge_length);
    finish(layer->face_area);
    finish(layer->dihedral_angle);
  }
}

}  // namespace quality
}  // namespace vorocrust
