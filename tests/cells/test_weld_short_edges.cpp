// Welding short edges on a clipped mesh of a box: cells stay closed, no edge stays shorter than
// the fraction, the volume moves by no more than the welded points' moves allow, faces leave
// their planes by about the fraction, and a fraction below every edge changes nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "cells/weld_short_edges.hpp"
#include "clipping/clip_cells.hpp"
#include "clipping/poisson_disk_seeds.hpp"
#include "surface_builder.hpp"
#include "vorocrust/regions.hpp"

namespace vorocrust::weld_test {

inline constexpr double kRadius = 0.12;

static VoronoiMesh clipped_box() {
  test::SurfaceBuilder b;
  b.box(Point::Zero(), Point(1, 0.8, 0.6));
  SurfaceMesh domain = b.mesh;
  label_regions(domain);
  std::vector<Seed> seeds = clipping::poisson_disk_seeds(domain, 1, kRadius, 5);
  const std::size_t materials_end = seeds.size();
  for (const Seed& s : clipping::outside_seeds(domain, 1.5 * kRadius, kRadius)) seeds.push_back(s);
  return clipping::clip_cells(clipping::material_diagrams(seeds, materials_end), domain);
}

static double shortest_edge(const VoronoiMesh& m) {
  double shortest = INFINITY;
  for (const VoronoiFace& f : m.faces) {
    for (std::size_t k = 0; k < f.points.size(); ++k) {
      shortest = std::min(shortest, (m.points[f.points[k]] - m.points[f.points[(k + 1) % f.points.size()]]).norm());
    }
  }
  return shortest;
}

static void expect_closed(const VoronoiMesh& m) {
  for (std::size_t c = 0; c < m.cells.size(); ++c) {
    std::map<std::pair<Index, Index>, int> edges;
    for (Index f : m.cells[c].faces) {
      std::vector<Index> p = m.faces[f].points;
      ASSERT_GE(p.size(), 3u);
      if (m.faces[f].owner != static_cast<std::int32_t>(c)) std::reverse(p.begin(), p.end());
      for (std::size_t k = 0; k < p.size(); ++k) ++edges[{p[k], p[(k + 1) % p.size()]}];
    }
    for (const auto& [e, count] : edges) {
      ASSERT_EQ(count, 1) << "cell " << c;
      ASSERT_EQ(edges.count({e.second, e.first}), 1u) << "cell " << c << " is open";
    }
  }
}

static double summed_cell_volume(const VoronoiMesh& m) {
  double v = 0;
  for (const VoronoiCell& c : m.cells) v += c.volume;
  return v;
}

TEST(WeldShortEdges, NoEdgeShorterThanTheFractionAndCellsStayClosed) {
  VoronoiMesh m = clipped_box();
  const double before = shortest_edge(m);
  ASSERT_LT(before, 0.02 * kRadius);  // clipping leaves short edges along the box
  const std::size_t cells = m.cells.size();
  const double fraction = 0.05;
  const WeldStats stats = cells::weld_short_edges(m, std::vector<double>(cells, kRadius), fraction);
  EXPECT_GT(stats.welded_points, 0u);
  EXPECT_EQ(m.cells.size(), cells);
  expect_closed(m);
  EXPECT_NEAR(stats.shortest_edge_before, before / kRadius, 1e-12);
  EXPECT_NEAR(stats.shortest_edge_after, shortest_edge(m) / kRadius, 1e-12);
  if (stats.kept_edges == 0) {
    EXPECT_GE(shortest_edge(m), fraction * kRadius * (1 - 1e-12));
  }
  EXPECT_LT(stats.kept_edges, stats.short_edges / 10);
  // Points move by less than a short edge's length: the volume by less than that times the area.
  const double area = 2 * (0.8 + 0.48 + 0.6);
  EXPECT_NEAR(summed_cell_volume(m), 0.48, fraction * kRadius * area);
  EXPECT_GT(stats.max_non_planarity, 0);
  EXPECT_LT(stats.max_non_planarity, 2 * fraction);
  for (const VoronoiCell& c : m.cells) EXPECT_GT(c.volume, 0);
}

TEST(WeldShortEdges, AFractionBelowEveryEdgeChangesNothing) {
  VoronoiMesh m = clipped_box();
  const VoronoiMesh before = m;
  const WeldStats stats =
      cells::weld_short_edges(m, std::vector<double>(m.cells.size(), kRadius), 0.5 * shortest_edge(m) / kRadius);
  EXPECT_EQ(stats.short_edges, 0u);
  EXPECT_EQ(stats.welded_points, 0u);
  EXPECT_EQ(m.points, before.points);
  ASSERT_EQ(m.faces.size(), before.faces.size());
  for (std::size_t f = 0; f < m.faces.size(); ++f) EXPECT_EQ(m.faces[f].points, before.faces[f].points);
}

}  // namespace vorocrust::weld_test
