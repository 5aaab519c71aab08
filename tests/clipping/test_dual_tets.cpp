// The tetrahedra dual to clipped cells, against a brute force over every four sites (empty
// circumsphere, circumcentre inside the domain), and the shape measures on tetrahedra whose
// figures are known.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <vector>

#include "clipping/clip_cells.hpp"
#include "clipping/dual_tets.hpp"
#include "clipping/clipped_box.hpp"
#include "vorocrust/cells.hpp"
#include "vorocrust/regions.hpp"

namespace vorocrust::dual_tets_test {

Point circumcentre(const std::array<Point, 4>& v) {
  Eigen::Matrix3d m;
  Eigen::Vector3d rhs;
  for (int k = 0; k < 3; ++k) {
    m.row(k) = (v[k + 1] - v[0]).transpose();
    rhs[k] = (v[k + 1] - v[0]).squaredNorm() / 2;
  }
  return v[0] + m.fullPivLu().solve(rhs);
}

TEST(DualTets, ShapesOfKnownTetrahedra) {
  const clipping::TetShape regular =
      clipping::tet_shape(Point(1, 1, 1), Point(1, -1, -1), Point(-1, 1, -1), Point(-1, -1, 1));
  EXPECT_NEAR(regular.min_dihedral, std::acos(1.0 / 3) * 180 / std::numbers::pi, 1e-9);
  EXPECT_NEAR(regular.max_dihedral, regular.min_dihedral, 1e-9);
  EXPECT_NEAR(regular.radius_ratio, 1, 1e-12);
  EXPECT_NEAR(regular.q4, 1, 1e-12);
  EXPECT_NEAR(regular.volume, 8.0 / 3, 1e-12);
  EXPECT_NEAR(regular.circumradius, std::sqrt(3.0), 1e-12);
  // A sliver: four corners of a square, two lifted a little.
  const clipping::TetShape sliver =
      clipping::tet_shape(Point(0, 0, 0), Point(1, 1, 0), Point(1, 0, 0.01), Point(0, 1, 0.01));
  EXPECT_LT(sliver.min_dihedral, 2);
  EXPECT_GT(sliver.max_dihedral, 178);
  EXPECT_LT(sliver.radius_ratio, 0.05);
  EXPECT_LT(sliver.q4, 0.1);  // Q4 goes as the volume to the 2/3: slowly
  // A cube's corner: 90 degrees between its sides, arccos(1/sqrt(3)) between a side and the
  // slanted face.
  const clipping::TetShape corner = clipping::tet_shape(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1));
  EXPECT_NEAR(corner.max_dihedral, 90, 1e-9);
  EXPECT_NEAR(corner.min_dihedral, std::acos(1 / std::sqrt(3.0)) * 180 / std::numbers::pi, 1e-9);
  EXPECT_NEAR(corner.circumradius, std::sqrt(3.0) / 2, 1e-12);
}

// Random sites in a box: the dual tetrahedra are exactly the four-site sets whose circumsphere
// holds no other site and whose circumcentre lies inside the box, each with positive volume.
TEST(DualTets, AreTheDelaunayTetrahedraWithTheirCircumcentreInside) {
  const Point lo(0, 0, 0), hi(1.3, 1, 0.8);
  std::mt19937_64 random(12);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point> sites;
  for (int i = 0; i < 40; ++i) sites.push_back(lo + (hi - lo).cwiseProduct(Point(u(random), u(random), u(random))));
  const VoronoiMesh clipped = test::clipped_in_box(test::interior_seeds(sites), lo, hi);
  const clipping::DualTets dual = clipping::dual_tets(clipped);
  EXPECT_EQ(dual.degenerate_points, 0u);
  std::set<std::array<std::uint32_t, 4>> found;
  for (std::size_t t = 0; t < dual.tets.size(); ++t) {
    std::array<std::uint32_t, 4> cells = dual.tets[t];
    const auto& s = [&](int k) -> const Point& { return clipped.cells[cells[k]].site; };
    EXPECT_GT((s(1) - s(0)).cross(s(2) - s(0)).dot(s(3) - s(0)), 0);
    EXPECT_EQ(dual.material[t], 1);
    std::array<std::uint32_t, 4> by_seed;
    for (int k = 0; k < 4; ++k) by_seed[k] = clipped.cells[cells[k]].seed;
    std::sort(by_seed.begin(), by_seed.end());
    EXPECT_TRUE(found.insert(by_seed).second);
  }
  std::set<std::array<std::uint32_t, 4>> expected;
  const auto n = static_cast<std::uint32_t>(sites.size());
  for (std::uint32_t a = 0; a < n; ++a) {
    for (std::uint32_t b = a + 1; b < n; ++b) {
      for (std::uint32_t c = b + 1; c < n; ++c) {
        for (std::uint32_t d = c + 1; d < n; ++d) {
          const std::array<Point, 4> v{sites[a], sites[b], sites[c], sites[d]};
          if (std::abs((v[1] - v[0]).cross(v[2] - v[0]).dot(v[3] - v[0])) < 1e-12) continue;
          const Point centre = circumcentre(v);
          if ((centre.array() <= lo.array()).any() || (centre.array() >= hi.array()).any()) continue;
          const double r2 = (centre - v[0]).squaredNorm();
          bool empty = true;
          for (std::uint32_t e = 0; e < n && empty; ++e) {
            empty = e == a || e == b || e == c || e == d || (sites[e] - centre).squaredNorm() > r2 * (1 + 1e-9);
          }
          if (empty) expected.insert({a, b, c, d});
        }
      }
    }
  }
  EXPECT_GT(expected.size(), 20u);
  EXPECT_EQ(found, expected);
}

// The body-centred cubic lattice's Delaunay tetrahedra are all congruent: dihedral angles of 60
// and 90 degrees (Sommerville's tetrahedron).
TEST(DualTets, BodyCentredLatticeGivesSommervilleTetrahedra) {
  const Point lo(0.0137, 0.0291, 0.0419), hi(3.0137, 3.0291, 3.0419);
  std::vector<Point> sites;
  for (int i = 0; i <= 3; ++i) {
    for (int j = 0; j <= 3; ++j) {
      for (int k = 0; k <= 3; ++k) {
        for (const Point& p : {Point(i, j, k), Point(i + 0.5, j + 0.5, k + 0.5)}) {
          if ((p.array() > lo.array()).all() && (p.array() < hi.array()).all()) sites.push_back(p);
        }
      }
    }
  }
  const VoronoiMesh clipped = test::clipped_in_box(test::interior_seeds(sites), lo, hi);
  const clipping::DualTets dual = clipping::dual_tets(clipped);
  ASSERT_GT(dual.tets.size(), 50u);
  const auto site = [&](std::uint32_t c) -> const Point& { return clipped.cells[c].site; };
  for (const auto& t : dual.tets) {
    const clipping::TetShape s = clipping::tet_shape(site(t[0]), site(t[1]), site(t[2]), site(t[3]));
    EXPECT_NEAR(s.min_dihedral, 60, 1e-6);
    EXPECT_NEAR(s.max_dihedral, 90, 1e-6);
    EXPECT_NEAR(s.volume, 1.0 / 12, 1e-12);  // six per site, whose cell has volume 1/2
  }
  const DualTetFigures f = clipping::measure_dual_tets(clipped);
  EXPECT_EQ(f.tets, dual.tets.size());
  EXPECT_NEAR(f.volume, static_cast<double>(f.tets) / 12, 1e-9);
  EXPECT_NEAR(f.mean_min_dihedral, 60, 1e-6);
  EXPECT_NEAR(f.min_min_dihedral, 60, 1e-6);
  EXPECT_NEAR(f.max_max_dihedral, 90, 1e-6);
  const clipping::TetShape one =
      clipping::tet_shape(Point(0, 0, 0), Point(1, 0, 0), Point(0.5, 0.5, 0.5), Point(0.5, 0.5, -0.5));
  EXPECT_NEAR(f.mean_q4, one.q4, 1e-9);
  EXPECT_NEAR(f.min_q4, one.q4, 1e-9);
  EXPECT_NEAR(f.min_radius_ratio, one.radius_ratio, 1e-9);
}

}  // namespace vorocrust::dual_tets_test
