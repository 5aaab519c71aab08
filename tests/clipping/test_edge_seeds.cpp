// Ebeida and Mitchell's seeds on reflex edges, on an L-shaped prism (one reflex edge, the vertical
// edge at x = y = 1): seeds along it r / sqrt(2) apart, every point of it nearest an edge seed,
// interior seeds at least r from all, and the clipped cells of edge seeds star-shaped about their
// seeds (every face seen from the seed from inside), where a cell wrapping round the edge is not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "clipping/clip_cells.hpp"
#include "clipping/edge_seeds.hpp"
#include "clipping/poisson_disk_seeds.hpp"
#include "surface_builder.hpp"
#include "vorocrust/regions.hpp"

namespace vorocrust::edge_seeds_test {

// The L of the unit squares [0,1]x[0,1], [1,2]x[0,1] and [0,1]x[1,2], from z = 0 to 1.
static SurfaceMesh l_prism() {
  test::SurfaceBuilder b;
  const auto at = [](double x, double y, double z) { return Point(x, y, z); };
  for (const auto& [i, j] : {std::pair(0, 0), std::pair(1, 0), std::pair(0, 1)}) {
    b.quad(at(i, j, 0), at(i, j + 1, 0), at(i + 1, j + 1, 0), at(i + 1, j, 0));
    b.quad(at(i, j, 1), at(i + 1, j, 1), at(i + 1, j + 1, 1), at(i, j + 1, 1));
  }
  const std::vector<std::pair<double, double>> outline{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1},
                                                       {1, 2}, {0, 2}, {0, 1}};
  for (std::size_t k = 0; k < outline.size(); ++k) {
    const auto [px, py] = outline[k];
    const auto [qx, qy] = outline[(k + 1) % outline.size()];
    b.quad(at(px, py, 0), at(qx, qy, 0), at(qx, qy, 1), at(px, py, 1));
  }
  SurfaceMesh mesh = b.mesh;
  label_regions(mesh);
  return mesh;
}

TEST(EdgeSeeds, ReflexEdgeIsProtected) {
  const SurfaceMesh domain = l_prism();
  const double r = 0.2, r_e = r / std::sqrt(2.0);
  const std::vector<Seed> edge = clipping::reflex_edge_seeds(domain, 1, r, 30, 7);
  ASSERT_GE(edge.size(), 5u);
  for (const Seed& s : edge) {
    EXPECT_EQ(s.kind, SeedKind::Surface);
    // On the reflex edge, moved into the material by a thousandth of r_e.
    EXPECT_NEAR(std::hypot(s.position.x() - 1, s.position.y() - 1), 0, 2e-3 * r_e);
    EXPECT_LE(s.position.x(), 1 + 1e-12);
    EXPECT_LE(s.position.y(), 1 + 1e-12);
  }
  for (std::size_t i = 0; i < edge.size(); ++i) {
    for (std::size_t j = i + 1; j < edge.size(); ++j) {
      EXPECT_GT((edge[i].position - edge[j].position).norm(), r_e * (1 - 3e-3));
    }
  }
  const std::vector<Seed> seeds = clipping::poisson_disk_seeds(domain, 1, r, 7, edge);
  ASSERT_GT(seeds.size(), edge.size());
  for (std::size_t i = edge.size(); i < seeds.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) EXPECT_GE((seeds[i].position - seeds[j].position).norm(), r);
  }
  // Every point of the reflex edge is nearest an edge seed.
  for (int k = 0; k <= 100; ++k) {
    const Point p(1, 1, k / 100.0);
    const auto nearest = std::min_element(seeds.begin(), seeds.end(), [&](const Seed& a, const Seed& b) {
      return (a.position - p).norm() < (b.position - p).norm();
    });
    EXPECT_EQ(nearest->kind, SeedKind::Surface) << "z " << p.z();
  }
  // The clipped cells of edge seeds are star-shaped about their seeds.
  std::vector<Seed> all = seeds;
  for (const Seed& s : clipping::outside_seeds(domain, 1.5 * r, r)) all.push_back(s);
  const VoronoiMesh m = clipping::clip_cells(clipping::material_diagrams(all, seeds.size()), domain);
  double volume = 0;
  for (const VoronoiCell& c : m.cells) volume += c.volume;
  EXPECT_NEAR(volume, 3, 1e-12);
  for (std::size_t c = 0; c < edge.size(); ++c) {
    const Point& x = m.cells[c].site;
    for (Index f : m.cells[c].faces) {
      std::vector<Index> polygon = m.faces[f].points;
      if (m.faces[f].owner != static_cast<std::int32_t>(c)) std::reverse(polygon.begin(), polygon.end());
      // The face's plane (its area vector, the face may be an L about the edge) has the seed
      // on its inner side.
      Point area = Point::Zero();
      for (std::size_t k = 0; k < polygon.size(); ++k) {
        area += m.points[polygon[k]].cross(m.points[polygon[(k + 1) % polygon.size()]]);
      }
      EXPECT_GT(area.normalized().dot(m.points[polygon[0]] - x), 0)
          << "edge seed " << c << " does not see its face " << f;
    }
  }
}

}  // namespace vorocrust::edge_seeds_test
