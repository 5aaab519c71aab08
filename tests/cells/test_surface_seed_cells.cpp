// The cells of a real VoroCrust seed set: the surface seeds of cgal_joint.off (paper 2.4), where
// every ball centre is a Voronoi vertex of many cospherical seeds. The inside seeds' cells,
// bounded by the outside seeds across the surface, must come out conforming, and their boundary
// must be the surface stage's output surface: one triangle of ball centres per face.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <set>

#include "cells/mesh_checks.hpp"
#include "core/surface_measures.hpp"
#include "test_support.hpp"
#include "vorocrust/cells.hpp"
#include "vorocrust/mesher.hpp"
#include "vorocrust/read_mesh.hpp"

namespace vorocrust {
namespace {

TEST(SurfaceSeedCells, JointCellsAreBoundedByTheOutputSurface) {
  MeshOptions options;
  options.stop_after = Stage::Surface;
  const MeshResult r = generate_mesh(read_mesh(test::model("cgal_joint.off")), options);
  const VoronoiMesh m = compute_cells(r.seeds);

  test::expect_valid(m, r.seeds);
  std::size_t inside = 0;
  for (const Seed& s : r.seeds) inside += s.region == kInsideRegion;
  ASSERT_EQ(m.cells.size(), inside);

  // The boundary faces are the surface's triangles: the same corner points, up to welding.
  const double size = (r.surface.vertices.front() - r.surface.vertices.back()).norm() + 1;
  using Key = std::array<std::array<long long, 3>, 3>;
  const auto key = [&](const std::array<Point, 3>& t) {
    Key k;
    for (int i = 0; i < 3; ++i) {
      for (int d = 0; d < 3; ++d) k[i][d] = std::llround(t[i][d] / (1e-7 * size));
    }
    std::sort(k.begin(), k.end());
    return k;
  };
  std::set<Key> triangles;
  for (const Triangle& t : r.surface.triangles) {
    triangles.insert(key({r.surface.vertices[t[0]], r.surface.vertices[t[1]], r.surface.vertices[t[2]]}));
  }
  std::size_t boundary = 0, matched = 0;
  for (const VoronoiFace& f : m.faces) {
    if (f.neighbour != kNoCell) continue;
    ++boundary;
    EXPECT_EQ(f.regions, (RegionPair{kInsideRegion, kOutsideRegion}));
    if (f.points.size() == 3 && triangles.count(key({m.points[f.points[0]], m.points[f.points[1]], m.points[f.points[2]]}))) {
      ++matched;
    }
  }
  EXPECT_EQ(boundary, r.surface.num_faces());
  EXPECT_EQ(matched, boundary);

  double volume = 0;
  for (const VoronoiCell& c : m.cells) volume += c.volume;
  std::vector<Index> all(r.surface.num_faces());
  std::iota(all.begin(), all.end(), Index{0});
  const double enclosed = enclosed_volume(r.surface, all);
  EXPECT_NEAR(volume, enclosed, 1e-9 * enclosed);
}

}  // namespace
}  // namespace vorocrust
