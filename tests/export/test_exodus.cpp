// Exodus II files as write_exodus writes them, read back by the library's reader, which goes
// through the Exodus library itself: the blocks, their names and volumes, the faces' cells and
// regions, the side sets, and the refusals.
#include <gtest/gtest.h>

#include <fstream>
#include <map>

#include "cells/seed_sets.hpp"
#include "test_support.hpp"
#include "vorocrust/cells.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/exodus.hpp"

namespace vorocrust {
namespace {

namespace fs = std::filesystem;

VoronoiMesh two_materials() {
  VoronoiMesh mesh = compute_cells(test::lattice_seeds(8, 0.3, test::split_box_region(1.5, 5.5, 3.5), 5));
  mesh.region_names = {"air", "sand", "cap rock"};
  return mesh;
}

std::map<std::int32_t, double> volume_by_region(const VoronoiMesh& mesh) {
  std::map<std::int32_t, double> volume;
  for (const VoronoiCell& c : mesh.cells) volume[c.region] += c.volume;
  return volume;
}

TEST(Exodus, ReadsBackTheCellsFacesRegionsAndNames) {
  const VoronoiMesh mesh = two_materials();
  const test::TempDir dir("exodus");
  write_exodus(mesh, dir / "mesh.exo");
  const VoronoiMesh back = read_exodus(dir / "mesh.exo");

  ASSERT_EQ(back.points.size(), mesh.points.size());
  for (std::size_t p = 0; p < mesh.points.size(); ++p) EXPECT_EQ(back.points[p], mesh.points[p]);
  ASSERT_EQ(back.cells.size(), mesh.cells.size());
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    const VoronoiCell &a = mesh.cells[c], &b = back.cells[c];
    EXPECT_EQ(b.region, a.region) << c;
    EXPECT_EQ(b.seed, a.seed) << c;
    EXPECT_EQ(b.site, a.site) << c;
    EXPECT_EQ(b.faces, a.faces) << c;
    EXPECT_NEAR(b.volume, a.volume, 1e-12 * a.volume) << c;
    EXPECT_LT((b.centroid - a.centroid).norm(), 1e-12) << c;
  }
  ASSERT_EQ(back.faces.size(), mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const VoronoiFace &a = mesh.faces[f], &b = back.faces[f];
    EXPECT_EQ(b.points, a.points) << f;
    EXPECT_EQ(b.owner, a.owner) << f;
    EXPECT_EQ(b.neighbour, a.neighbour) << f;
    EXPECT_EQ(b.regions.back, a.regions.back) << f;
    EXPECT_EQ(b.regions.front, a.regions.front) << f;
  }
  // Names as words, as the OpenFOAM case's zones: "cap rock" is cap_rock.
  EXPECT_EQ(back.region_names, (std::vector<std::string>{"air", "sand", "cap_rock"}));
  EXPECT_EQ(volume_by_region(back), volume_by_region(mesh));
}

TEST(Exodus, BoundaryFacesKeepTheRegionAcrossFromTheSideSets) {
  // Cells for material 1 only: its faces toward material 2 are boundary faces with 2 across.
  const auto seeds = test::lattice_seeds(8, 0.3, test::split_box_region(1.5, 5.5, 3.5), 5);
  VoronoiMesh mesh = compute_cells(seeds, {.materials = {1}});
  const test::TempDir dir("exodus_across");
  write_exodus(mesh, dir / "mesh.exo");
  const VoronoiMesh back = read_exodus(dir / "mesh.exo");
  std::map<std::int32_t, std::size_t> across;
  for (const VoronoiFace& f : back.faces) {
    if (f.neighbour == kNoCell) ++across[f.regions.front];
  }
  EXPECT_GT(across[0], 0u);
  EXPECT_GT(across[2], 0u);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) EXPECT_EQ(back.faces[f].regions.front, mesh.faces[f].regions.front);
  EXPECT_EQ(back.region_names, (std::vector<std::string>{"outside", "material1", "material2"}));
}

TEST(Exodus, RefusesWhatItCannotWriteOrRead) {
  VoronoiMesh mesh = two_materials();
  const test::TempDir dir("exodus_refusals");
  try {
    write_exodus(mesh, dir / "missing" / "mesh.exo");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Output);
    EXPECT_NE(std::string(e.what()).find("mesh.exo"), std::string::npos) << e.what();
  }
  mesh.cells.front().region = 0;
  EXPECT_THROW(write_exodus(mesh, dir / "zero.exo"), Error);
  EXPECT_TRUE(fs::is_empty(dir.path()));  // nothing half-written

  for (const char* text : {"", "not a netCDF file\n", "CDF\x01\x00\x00\x00\x00"}) {
    std::ofstream(dir / "bad.exo", std::ios::binary) << text;
    try {
      read_exodus(dir / "bad.exo");
      FAIL() << "no error for " << text;
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::UnreadableInput);
      EXPECT_NE(std::string(e.what()).find("bad.exo"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(read_exodus(dir / "absent.exo"), Error);
}

}  // namespace
}  // namespace vorocrust
