// Cells cut again only about added seeds (cells/growing_cells.hpp) must be the cells of all the
// seeds cut afresh, bit for bit: the skew repair relies on it, and so does rebuilding a mesh from
// its seeds.csv.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "cells/growing_cells.hpp"
#include "cells/mesh_checks.hpp"
#include "cells/seed_sets.hpp"
#include "test_support.hpp"
#include "vorocrust/cell_quality.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/face_skewness.hpp"
#include "vorocrust/mesher.hpp"
#include "vorocrust/read_mesh.hpp"

namespace vorocrust {
namespace {

void expect_same_mesh(const VoronoiMesh& a, const VoronoiMesh& b) {
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t p = 0; p < a.points.size(); ++p) ASSERT_EQ(a.points[p], b.points[p]) << "point " << p;
  ASSERT_EQ(a.faces.size(), b.faces.size());
  for (std::size_t f = 0; f < a.faces.size(); ++f) {
    ASSERT_EQ(a.faces[f].points, b.faces[f].points) << "face " << f;
    ASSERT_EQ(a.faces[f].owner, b.faces[f].owner) << "face " << f;
    ASSERT_EQ(a.faces[f].neighbour, b.faces[f].neighbour) << "face " << f;
  }
  ASSERT_EQ(a.cells.size(), b.cells.size());
  for (std::size_t c = 0; c < a.cells.size(); ++c) {
    ASSERT_EQ(a.cells[c].faces, b.cells[c].faces) << "cell " << c;
    ASSERT_EQ(a.cells[c].volume, b.cells[c].volume) << "cell " << c;
  }
}

// The seeds with every `stride`-th one moved to the end, and how many stay in front.
std::pair<std::vector<Seed>, std::size_t> held_back(const std::vector<Seed>& seeds, std::size_t stride) {
  std::vector<Seed> front, back;
  for (std::size_t s = 0; s < seeds.size(); ++s) (s % stride == stride - 1 ? back : front).push_back(seeds[s]);
  const std::size_t kept = front.size();
  front.insert(front.end(), back.begin(), back.end());
  return {front, kept};
}

void expect_same_faces(const std::vector<cells::CutFace>& a, const std::vector<cells::CutFace>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    ASSERT_EQ(a[k].owner_seed, b[k].owner_seed) << "face " << k;
    ASSERT_EQ(a[k].neighbour_seed, b[k].neighbour_seed) << "face " << k;
    ASSERT_EQ(a[k].skewness, b[k].skewness) << "face " << k;
    ASSERT_EQ(a[k].geometry.area, b[k].geometry.area) << "face " << k;
    ASSERT_EQ(a[k].owner_centroid, b[k].owner_centroid) << "face " << k;
    ASSERT_EQ(a[k].neighbour_centroid, b[k].neighbour_centroid) << "face " << k;
  }
}

void expect_growing_matches_fresh(const std::vector<Seed>& seeds, std::size_t stride) {
  // A low threshold, so that many faces count and the cells next to those cut again matter.
  constexpr double kThreshold = 0.3;
  const auto [all, kept] = held_back(seeds, stride);
  cells::GrowingCells growing(std::vector<Seed>(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(kept)), {});
  growing.skew_faces(kThreshold);
  // In two steps, as the repair rounds add theirs, the skew faces measured after each.
  const std::size_t middle = kept + (all.size() - kept) / 2;
  growing.add_seeds(std::vector<Seed>(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(middle)));
  growing.skew_faces(kThreshold);
  growing.add_seeds(all);
  const std::vector<cells::CutFace> skew = growing.skew_faces(kThreshold);
  EXPECT_GT(skew.size(), 10u);
  expect_same_faces(skew, cells::GrowingCells(all, {}).skew_faces(kThreshold));
  const VoronoiMesh fresh = compute_cells(all);
  test::expect_valid(fresh, all);
  expect_same_mesh(growing.mesh(), fresh);
}

TEST(GrowingCells, AddedSeedsGiveTheCellsOfAllSeedsOnAJitteredLattice) {
  const auto seeds = test::lattice_seeds(14, 0.3, [](const Point& p) {
    return (p.array() > 0.5).all() && (p.array() < 12.5).all() ? kInsideRegion : kOutsideRegion;
  });
  expect_growing_matches_fresh(seeds, 53);
}

TEST(GrowingCells, AddedSeedsGiveTheCellsOfAllSeedsOfAWholeRun) {
  // A run's seeds: surface seeds cospherical about every ball centre, poles, interior and
  // outside seeds; one in 97 comes later, about 120 in all.
  MeshOptions options;
  options.seed = 3;
  const MeshResult r = generate_mesh(read_mesh(test::model("cgal_joint.off")), options);
  expect_growing_matches_fresh(r.seeds, 97);
}

TEST(GrowingCells, AFrameThatChangesCutsEveryCellAgain) {
  auto seeds = test::lattice_seeds(8, 0.3, [](const Point& p) {
    return (p.array() > 0.5).all() && (p.array() < 6.5).all() ? kInsideRegion : kOutsideRegion;
  });
  cells::GrowingCells growing(seeds, {});
  Seed far = seeds.front();
  far.position = Point(-20, 3, 3);  // outside the seeds' box: another frame
  seeds.push_back(far);
  growing.add_seeds(seeds);
  expect_same_mesh(growing.mesh(), compute_cells(seeds));
}

// The skew repair finds its faces on the cells as cut: every face of the mesh, once, with its
// measures to round-off, and no face that welding drops.
TEST(GrowingCells, CutFacesAreTheMeshFacesWithTheirSkewness) {
  MeshOptions options;
  options.seed = 3;
  const MeshResult r = generate_mesh(read_mesh(test::model("cgal_joint.off")), options);
  cells::GrowingCells growing(r.seeds, {});
  const VoronoiMesh mesh = growing.mesh();
  const std::vector<cells::CutFace> cut = growing.skew_faces(-1);
  std::map<std::pair<Index, std::int32_t>, const cells::CutFace*> by_seeds;
  for (const cells::CutFace& f : cut) by_seeds[{f.owner_seed, f.neighbour_seed}] = &f;
  ASSERT_EQ(by_seeds.size(), cut.size());  // each face once
  std::size_t skew_in_mesh = 0, skew_cut = 0;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const VoronoiFace& face = mesh.faces[f];
    const auto it = by_seeds.find({face.owner_seed, static_cast<std::int32_t>(face.neighbour_seed)});
    ASSERT_NE(it, by_seeds.end()) << "face " << f;
    const cells::CutFace& c = *it->second;
    EXPECT_EQ(c.between_cells, face.neighbour != kNoCell);
    const FaceGeometry g = face_geometry(mesh, f);
    EXPECT_NEAR(c.geometry.area, g.area, 1e-6 * g.area + 1e-15);
    EXPECT_LT((c.geometry.centroid - g.centroid).norm(), 1e-6 * std::sqrt(g.area) + 1e-12);
    const double skewness = face_skewness(mesh, f);
    EXPECT_NEAR(c.skewness, skewness, 1e-6 * skewness) << "face " << f;
    skew_in_mesh += skewness > 0.5;
    skew_cut += c.skewness > 0.5;
    by_seeds.erase(it);
  }
  // The faces welding drops (fewer than three points apart) are left out as well.
  EXPECT_TRUE(by_seeds.empty()) << by_seeds.size() << " cut faces are not in the mesh";
  EXPECT_GT(skew_in_mesh, 0u);  // the test sees skew faces
  EXPECT_EQ(skew_cut, skew_in_mesh);
  EXPECT_EQ(growing.skew_faces(0.5).size(), skew_cut);
}

TEST(GrowingCells, SeedsCanOnlyBeAdded) {
  auto seeds = test::lattice_seeds(5, 0.2, [](const Point& p) {
    return (p.array() > 0.5).all() && (p.array() < 3.5).all() ? kInsideRegion : kOutsideRegion;
  });
  cells::GrowingCells growing(seeds, {});
  seeds.pop_back();
  EXPECT_THROW(growing.add_seeds(seeds), Error);
}

// The split of cells too long finds them on the cells as cut: the cells the quality of the mesh
// puts above the bound, with their centroids to round-off; after seeds are added, those of all
// the seeds cut afresh.
TEST(GrowingCells, LongCellsAreTheMeshCellsAboveTheBound) {
  MeshOptions options;
  options.seed = 3;
  const MeshResult r = generate_mesh(read_mesh(test::model("cgal_joint.off")), options);
  constexpr double kBound = 3.5;
  const auto [all, kept] = held_back(r.seeds, 97);
  cells::GrowingCells growing(std::vector<Seed>(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(kept)), {});
  growing.long_cells(kBound);
  growing.add_seeds(all);
  const std::vector<cells::LongCell> found = growing.long_cells(kBound);
  const VoronoiMesh mesh = growing.mesh();
  const CellQuality quality = measure_cell_quality(mesh);
  std::map<Index, const VoronoiCell*> above;
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    if (quality.cells[c].aspect_ratio > kBound * (1 + 1e-9)) above[mesh.cells[c].seed] = &mesh.cells[c];
  }
  EXPECT_GT(above.size(), 10u);
  std::size_t matched = 0;
  for (const cells::LongCell& cell : found) {
    const auto it = above.find(cell.seed);
    if (it == above.end()) continue;  // at the bound to round-off
    ++matched;
    EXPECT_LT((cell.centroid - it->second->centroid).norm(), 1e-9) << "seed " << cell.seed;
  }
  EXPECT_EQ(matched, above.size());
  EXPECT_LE(found.size(), above.size() + 2);
  const std::vector<cells::LongCell> fresh = cells::GrowingCells(all, {}).long_cells(kBound);
  ASSERT_EQ(fresh.size(), found.size());
  for (std::size_t k = 0; k < found.size(); ++k) {
    EXPECT_EQ(fresh[k].seed, found[k].seed);
    EXPECT_EQ(fresh[k].centroid, found[k].centroid);
  }
}

}  // namespace
}  // namespace vorocrust
