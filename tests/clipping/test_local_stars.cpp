// The Delaunay tetrahedra about single seeds, from their Voronoi cells among their neighbours,
// against those read from the whole clipped mesh, before and after a seed moves.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <set>
#include <vector>

#include "clipping/clipped_box.hpp"
#include "clipping/dual_tets.hpp"
#include "clipping/local_stars.hpp"

namespace vorocrust::local_stars_test {

using Tet = std::array<std::uint32_t, 4>;

const Point kLo(0, 0, 0), kHi(2, 1.5, 1);

// The dual tetrahedra of the clipped cells of `sites` in the box, by their seeds, ascending.
std::set<Tet> clipped_tets(const std::vector<Seed>& sites) {
  const VoronoiMesh clipped = test::clipped_in_box(sites, kLo, kHi);
  std::set<Tet> tets;
  for (const Tet& cells : clipping::dual_tets(clipped).tets) {
    Tet t;
    for (int i = 0; i < 4; ++i) t[i] = static_cast<std::uint32_t>(clipped.cells[cells[i]].seed);
    std::sort(t.begin(), t.end());
    tets.insert(t);
  }
  return tets;
}

// Every seed's local star is the clipped mesh's tetrahedra that have it.
void expect_same_stars(const clipping::LocalStars& local, const std::set<Tet>& tets, std::uint32_t seeds) {
  for (std::uint32_t s = 0; s < seeds; ++s) {
    std::vector<clipping::StarTet> star;
    std::vector<std::uint32_t> neighbours;
    ASSERT_TRUE(local.star(s, star, neighbours)) << "seed " << s;
    std::set<Tet> mine;
    for (const clipping::StarTet& t : star) mine.insert(t.seeds);
    std::set<Tet> expected;
    for (const Tet& t : tets) {
      if (std::find(t.begin(), t.end(), s) != t.end()) expected.insert(t);
    }
    EXPECT_EQ(mine, expected) << "seed " << s;
    for (const Tet& t : mine) {
      for (std::uint32_t u : t) {
        if (u != s) {
          EXPECT_NE(std::find(neighbours.begin(), neighbours.end(), u), neighbours.end());
        }
      }
    }
  }
}

TEST(LocalStars, AreTheClippedMeshsTetrahedraAboutEachSeed) {
  const SurfaceMesh box = test::labelled_box(kLo, kHi);
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Seed> sites;
  for (int i = 0; i < 300; ++i) {
    sites.push_back({kLo + (kHi - kLo).cwiseProduct(Point(u(random), u(random), u(random))), 1, 0, SeedKind::Interior});
  }
  const std::set<Tet> tets = clipped_tets(sites);
  ASSERT_GT(tets.size(), 800u);
  clipping::LocalStars local(sites, box, 1.0);
  expect_same_stars(local, tets, static_cast<std::uint32_t>(sites.size()));
  // Moved seeds change cubes of the grid: the stars follow them.
  for (std::uint32_t s : {0u, 17u, 150u}) {
    sites[s].position = kLo + (kHi - kLo).cwiseProduct(Point(u(random), u(random), u(random)));
    local.move(s, sites[s].position);
  }
  expect_same_stars(local, clipped_tets(sites), static_cast<std::uint32_t>(sites.size()));
  // Within too short a reach, the stars of a sparse set cannot be sure.
  const clipping::LocalStars short_reach(sites, box, 0.05);
  std::vector<clipping::StarTet> star;
  std::vector<std::uint32_t> neighbours;
  EXPECT_FALSE(short_reach.star(0, star, neighbours));
}

}  // namespace vorocrust::local_stars_test
