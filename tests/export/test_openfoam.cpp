// The OpenFOAM case read back as plain text: OpenFOAM's ordering rules (internal faces first,
// upper triangular, boundary faces in contiguous patches by region pair), every face once, normals
// from owner to neighbour, one cell zone per material. checkMesh itself runs in tests/cli.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "cells/seed_sets.hpp"
#include "test_support.hpp"
#include "vorocrust/cells.hpp"
#include "vorocrust/write_openfoam.hpp"

namespace vorocrust {
namespace {

namespace fs = std::filesystem;

// The text after the FoamFile header's closing brace.
std::string body(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream all;
  all << in.rdbuf();
  const std::string text = all.str();
  EXPECT_EQ(text.rfind("FoamFile\n{", 0), 0u) << path;
  return text.substr(text.find("}\n") + 2);
}

std::vector<long> labels(const fs::path& path) {
  std::istringstream in(body(path));
  std::size_t n = 0;
  char paren = 0;
  in >> n >> paren;
  std::vector<long> out(n);
  for (long& v : out) in >> v;
  return out;
}

std::vector<std::vector<long>> face_list(const fs::path& path) {
  std::string text = body(path);
  for (char& c : text) {
    if (c == '(' || c == ')') c = ' ';
  }
  std::istringstream in(text);
  std::size_t n = 0;
  in >> n;
  std::vector<std::vector<long>> out(n);
  for (auto& f : out) {
    std::size_t k = 0;
    in >> k;
    f.resize(k);
    for (long& v : f) in >> v;
  }
  return out;
}

struct PatchEntry {
  std::string name;
  long faces = 0, start = 0;
};

std::vector<PatchEntry> patches(const fs::path& path) {
  std::istringstream in(body(path));
  std::size_t n = 0;
  char paren = 0;
  in >> n >> paren;
  std::vector<PatchEntry> out(n);
  for (PatchEntry& p : out) {
    std::string word;
    in >> p.name;
    while (in >> word && word != "}") {
      if (word == "nFaces") in >> p.faces;
      if (word == "startFace") in >> p.start;
    }
  }
  return out;
}

TEST(OpenFoamCase, FollowsOpenFoamsOrderingRules) {
  const auto seeds = test::lattice_seeds(10, 0.3, test::split_box_region(1.5, 7.5, 4.5), 3);
  const VoronoiMesh mesh = compute_cells(seeds);
  const test::TempDir dir("openfoam");
  write_openfoam_case(mesh, dir.path());
  const fs::path poly = dir / "constant/polyMesh";
  for (const char* f : {"system/controlDict", "system/fvSchemes", "system/fvSolution"}) EXPECT_TRUE(fs::exists(dir / f)) << f;

  const auto faces = face_list(poly / "faces");
  const auto owner = labels(poly / "owner");
  const auto neighbour = labels(poly / "neighbour");
  ASSERT_EQ(faces.size(), mesh.faces.size());
  ASSERT_EQ(owner.size(), faces.size());
  std::size_t internal = 0;
  for (const VoronoiFace& f : mesh.faces) internal += f.neighbour != kNoCell;
  ASSERT_EQ(neighbour.size(), internal);

  // Upper triangular: internal faces by owner, then neighbour; owner below neighbour.
  for (std::size_t f = 0; f < internal; ++f) {
    EXPECT_LT(owner[f], neighbour[f]);
    if (f) {
      EXPECT_TRUE(owner[f - 1] < owner[f] || (owner[f - 1] == owner[f] && neighbour[f - 1] < neighbour[f])) << f;
    }
  }
  // Patches contiguous after the internal faces, named by region pair, covering the boundary.
  const auto list = patches(poly / "boundary");
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0].name, "material1_to_outside");
  EXPECT_EQ(list[1].name, "material2_to_outside");
  long next = static_cast<long>(internal);
  for (const PatchEntry& p : list) {
    EXPECT_EQ(p.start, next);
    next += p.faces;
    for (long f = p.start; f < p.start + p.faces; ++f) {
      EXPECT_EQ(mesh.cells[owner[f]].region, p.name == "material1_to_outside" ? 1 : 2);
    }
  }
  EXPECT_EQ(next, static_cast<long>(faces.size()));

  // Normals from owner to neighbour: along the link between their seeds.
  for (std::size_t f = 0; f < faces.size(); ++f) {
    Point area = Point::Zero();
    for (std::size_t k = 0; k < faces[f].size(); ++k) {
      area += mesh.points[faces[f][k]].cross(mesh.points[faces[f][(k + 1) % faces[f].size()]]);
    }
    const Point from = seeds[mesh.cells[owner[f]].seed].position;
    if (f < internal) {
      EXPECT_GT(area.dot(seeds[mesh.cells[neighbour[f]].seed].position - from), 0) << f;
    } else {
      Point centre = Point::Zero();
      for (long p : faces[f]) centre += mesh.points[p];
      EXPECT_GT(area.dot(centre / static_cast<double>(faces[f].size()) - from), 0) << f;
    }
  }
  // Every point used, every cell has faces.
  std::vector<int> used(mesh.points.size()), cell_faces(mesh.cells.size());
  for (const auto& f : faces) {
    for (long p : f) used[p] = 1;
  }
  for (std::size_t f = 0; f < faces.size(); ++f) {
    ++cell_faces[owner[f]];
    if (f < internal) ++cell_faces[neighbour[f]];
  }
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0);
  EXPECT_EQ(std::count(cell_faces.begin(), cell_faces.end(), 0), 0);

  const std::string zones = body(poly / "cellZones");
  EXPECT_NE(zones.find("material1\n{\n    type cellZone;"), std::string::npos);
  EXPECT_NE(zones.find("material2\n{\n    type cellZone;"), std::string::npos);
}

TEST(OpenFoamCase, NamesZonesAndPatchesAfterTheRegionsAndListsTheInterfaceAsAFaceZone) {
  const auto seeds = test::lattice_seeds(8, 0.3, test::split_box_region(1.5, 5.5, 3.5), 5);
  VoronoiMesh mesh = compute_cells(seeds);
  mesh.region_names = {"air", "dry sand", "rock"};
  const test::TempDir dir("openfoam-zones");
  write_openfoam_case(mesh, dir.path());
  const fs::path poly = dir / "constant/polyMesh";
  const auto list = patches(poly / "boundary");
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0].name, "dry_sand_to_air");
  EXPECT_EQ(list[1].name, "rock_to_air");
  const std::string cell_zones = body(poly / "cellZones");
  EXPECT_NE(cell_zones.find("dry_sand\n{\n    type cellZone;"), std::string::npos);

  // The face zone: the internal faces between the two materials, flipped where the owner is rock.
  const auto owner = labels(poly / "owner");
  const auto neighbour = labels(poly / "neighbour");
  std::istringstream in(body(poly / "faceZones"));
  std::string word, name;
  std::size_t zones = 0, n = 0, m = 0;
  char paren = 0;
  in >> zones >> paren >> name >> word >> word >> word;  // 1 ( name { type faceZone;
  ASSERT_EQ(zones, 1u);
  EXPECT_EQ(name, "dry_sand_to_rock");
  in >> word >> word >> n >> paren;  // faceLabels List<label> N (
  std::vector<long> faces(n);
  for (long& f : faces) in >> f;
  in >> paren >> paren >> word >> word >> m >> paren;  // ) ; flipMap List<bool> N (
  ASSERT_EQ(m, n);
  std::size_t expected = 0;
  for (std::size_t f = 0; f < neighbour.size(); ++f) {
    expected += mesh.cells[owner[f]].region != mesh.cells[neighbour[f]].region;
  }
  EXPECT_EQ(n, expected);
  EXPECT_GT(n, 0u);
  for (long f : faces) {
    int flip = -1;
    in >> flip;
    EXPECT_NE(mesh.cells[owner[f]].region, mesh.cells[neighbour[f]].region);
    EXPECT_EQ(flip, mesh.cells[owner[f]].region == 2 ? 1 : 0) << f;
  }
}

}  // namespace
}  // namespace vorocrust
