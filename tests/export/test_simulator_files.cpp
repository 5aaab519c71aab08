// TOUGH's MESH and PFLOTRAN's explicit grid as the writers write them: fixed-width fields, names,
// and the quantities of each record against the mesh. The files go through readers written from
// the formats' specifications in tests/cli/test_multi_material.py.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "cells/seed_sets.hpp"
#include "io/text_numbers.hpp"
#include "test_support.hpp"
#include "vorocrust/cells.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/mesher.hpp"
#include "vorocrust/read_mesh.hpp"
#include "vorocrust/write_pflotran.hpp"
#include "vorocrust/write_tough.hpp"
#include "vorocrust/write_volume_mesh.hpp"

namespace vorocrust {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> lines_of(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(FortranFields, FillTheirWidthWithAsManyDigitsAsFit) {
  EXPECT_EQ(io::fortran_e(12.3456789, 10), "1.2346E+01");
  EXPECT_EQ(io::fortran_e(-12.3456789, 10), "-1.235E+01");
  EXPECT_EQ(io::fortran_e(0.0, 10), "0.0000E+00");
  EXPECT_EQ(io::fortran_e(1e-120, 10), "1.000E-120");
  EXPECT_THROW(io::fortran_e(std::numeric_limits<double>::infinity(), 10), Error);
}

TEST(ToughMesh, NamesCellsWithThreeCharactersAndATwoDigitNumber) {
  EXPECT_EQ(tough_element_name(0), "A00 0");
  EXPECT_EQ(tough_element_name(99), "A0099");
  EXPECT_EQ(tough_element_name(100), "A01 0");
  EXPECT_EQ(tough_element_name(36 * 100), "A10 0");
  EXPECT_EQ(tough_element_name(26u * 36u * 36u * 100u - 1), "ZZZ99");
  EXPECT_THROW(tough_element_name(26u * 36u * 36u * 100u), Error);
  std::set<std::string> names;
  for (std::size_t c = 0; c < 20000; ++c) names.insert(tough_element_name(c));
  EXPECT_EQ(names.size(), 20000u);
}

TEST(ToughMesh, MaterialsAreFiveCharacterNamesTellingTheRegionsApart) {
  VoronoiMesh mesh;
  mesh.cells.resize(4);
  for (int c = 0; c < 4; ++c) mesh.cells[c].region = c + 1;
  mesh.region_names = {"outside", "region1", "region2", "sand", "%%"};
  const auto names = tough_material_names(mesh);
  EXPECT_EQ(names.at(1), "regi1");
  EXPECT_EQ(names.at(2), "regi2");
  EXPECT_EQ(names.at(3), "sand");
  EXPECT_EQ(names.at(4), "MAT04");
}

TEST(ToughMesh, RecordsHoldTheCellsAndTheirConnections) {
  const auto seeds = test::lattice_seeds(8, 0.3, test::split_box_region(1.5, 5.5, 3.5), 5);
  VoronoiMesh mesh = compute_cells(seeds);
  mesh.region_names = {"outside", "sand", "rock"};
  const test::TempDir dir("tough");
  write_tough_mesh(mesh, dir / "MESH");
  const auto lines = lines_of(dir / "MESH");
  ASSERT_EQ(lines.front(), "ELEME");
  std::size_t l = 1;
  double volume = 0;
  for (std::size_t c = 0; c < mesh.cells.size(); ++c, ++l) {
    const std::string& r = lines[l];
    ASSERT_EQ(r.size(), 80u) << r;
    EXPECT_EQ(r.substr(0, 5), tough_element_name(c));
    EXPECT_EQ(r.substr(15, 5), mesh.cells[c].region == 1 ? "sand " : "rock ");
    volume += std::stod(r.substr(20, 10));
    EXPECT_NEAR(std::stod(r.substr(20, 10)), mesh.cells[c].volume, 1e-4 * mesh.cells[c].volume);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(std::stod(r.substr(50 + 10 * k, 10)), mesh.cells[c].site[k], 1e-3);
  }
  EXPECT_NEAR(volume, total_volume(mesh), 1e-4 * total_volume(mesh));
  EXPECT_EQ(lines[l++], "");
  ASSERT_EQ(lines[l++], "CONNE");
  std::size_t connections = 0;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const VoronoiFace& face = mesh.faces[f];
    if (face.neighbour == kNoCell) continue;
    const std::string& r = lines[l++];
    ++connections;
    ASSERT_EQ(r.size(), 70u) << r;
    EXPECT_EQ(r.substr(0, 10), tough_element_name(face.owner) + tough_element_name(face.neighbour));
    const Point link = mesh.cells[face.neighbour].site - mesh.cells[face.owner].site;
    EXPECT_NEAR(std::stod(r.substr(30, 10)), link.norm() / 2, 1e-4 * link.norm());
    EXPECT_EQ(r.substr(30, 10), r.substr(40, 10));
    EXPECT_NEAR(std::stod(r.substr(50, 10)), face_geometry(mesh, f).area, 1e-4 * face_geometry(mesh, f).area);
    EXPECT_NEAR(std::stod(r.substr(60, 10)), -link.z() / link.norm(), 1e-3);
    int axis = 0;
    link.cwiseAbs().maxCoeff(&axis);
    EXPECT_EQ(r.substr(25, 5), "    " + std::to_string(axis + 1));
  }
  EXPECT_EQ(connections, count_interior_faces(mesh));
  EXPECT_EQ(lines[l++], "");
  EXPECT_EQ(l, lines.size());
}

TEST(Pflotran, GridRegionsAndBoundaryConnectionsOfEveryCellAndFace) {
  const auto seeds = test::lattice_seeds(8, 0.3, test::split_box_region(1.5, 5.5, 3.5), 5);
  const VoronoiMesh mesh = compute_cells(seeds);
  const test::TempDir dir("pflotran");
  write_pflotran(mesh, dir / "grid");
  std::ifstream uge(dir / "grid/mesh.uge");
  std::string card;
  std::size_t n = 0;
  uge >> card >> n;
  EXPECT_EQ(card, "CELLS");
  ASSERT_EQ(n, mesh.cells.size());
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t id = 0;
    Point p;
    double volume = 0;
    uge >> id >> p.x() >> p.y() >> p.z() >> volume;
    EXPECT_EQ(id, c + 1);
    EXPECT_EQ(p, mesh.cells[c].site);  // shortest round-trip form: exact
    EXPECT_EQ(volume, mesh.cells[c].volume);
  }
  std::size_t m = 0;
  uge >> card >> m;
  EXPECT_EQ(card, "CONNECTIONS");
  EXPECT_EQ(m, count_interior_faces(mesh));
  for (const char* file : {"material1.txt", "material2.txt", "material1_to_outside.ex", "material2_to_outside.ex"}) {
    EXPECT_TRUE(fs::exists(dir / "grid" / file)) << file;
  }
  std::size_t boundary = 0;
  for (const char* file : {"material1_to_outside.ex", "material2_to_outside.ex"}) {
    std::ifstream ex(dir / "grid" / file);
    std::size_t k = 0;
    ex >> card >> k;
    EXPECT_EQ(card, "CONNECTIONS");
    boundary += k;
  }
  EXPECT_EQ(boundary, mesh.faces.size() - count_interior_faces(mesh));
}

// A real run's tiny faces (area below 1e-4 of the larger cell's size squared, the size being the
// cube root of the volume) carry little, but a simulator must still see them: each is a
// connection in TOUGH's MESH and PFLOTRAN's grid, with its area.
TEST(SimulatorFiles, TinyFacesOfARealRunAreConnections) {
  MeshOptions options;
  options.seed = 1;
  const VoronoiMesh mesh = generate_mesh(read_mesh(test::model("cgal_joint.off")), options).cells;
  std::vector<std::size_t> interior;  // the connections' faces, in the order both files list them
  std::set<std::size_t> tiny;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const VoronoiFace& face = mesh.faces[f];
    if (face.neighbour == kNoCell) continue;
    const double size = std::cbrt(std::max(mesh.cells[face.owner].volume, mesh.cells[face.neighbour].volume));
    if (face_geometry(mesh, f).area < 1e-4 * size * size) tiny.insert(interior.size());
    interior.push_back(f);
  }
  ASSERT_GT(tiny.size(), 10u);
  const test::TempDir dir("tiny-faces");
  write_tough_mesh(mesh, dir / "MESH");
  write_pflotran(mesh, dir / "grid");

  const auto tough = lines_of(dir / "MESH");
  const auto conne = std::find(tough.begin(), tough.end(), "CONNE");
  ASSERT_NE(conne, tough.end());
  std::ifstream uge(dir / "grid/mesh.uge");
  std::string line;
  while (std::getline(uge, line) && line.rfind("CONNECTIONS", 0) != 0) {
  }
  ASSERT_EQ(line, "CONNECTIONS " + std::to_string(interior.size()));
  for (std::size_t k = 0; k < interior.size(); ++k) {
    ASSERT_TRUE(std::getline(uge, line));
    if (!tiny.count(k)) continue;
    const VoronoiFace& face = mesh.faces[interior[k]];
    const double area = face_geometry(mesh, interior[k]).area;
    const std::string& record = *(conne + 1 + static_cast<std::ptrdiff_t>(k));
    EXPECT_EQ(record.substr(0, 10), tough_element_name(face.owner) + tough_element_name(face.neighbour));
    EXPECT_NEAR(std::stod(record.substr(50, 10)), area, 1e-4 * area) << record;
    std::istringstream fields(line);
    long long owner = 0, neighbour = 0;
    double x = 0, y = 0, z = 0, listed = 0;
    fields >> owner >> neighbour >> x >> y >> z >> listed;
    EXPECT_EQ(owner, face.owner + 1);
    EXPECT_EQ(neighbour, face.neighbour + 1);
    EXPECT_EQ(listed, area);  // shortest round-trip form: exact
  }
}

TEST(VolumeFormats, WriteWhatIsAskedAndRemoveWhatAnEarlierRunLeft) {
  const auto seeds = test::lattice_seeds(5, 0.2, test::split_box_region(0.5, 3.5, 2.5), 2);
  const VoronoiMesh mesh = compute_cells(seeds);
  const test::TempDir dir("formats");
  write_volume_mesh(mesh, dir.path(), volume_format_names());
  for (const char* name : {"mesh.vtu", "case", "MESH", "pflotran", "mesh.exo"}) EXPECT_TRUE(fs::exists(dir / name)) << name;
  write_volume_mesh(mesh, dir.path(), {"tough"});
  EXPECT_TRUE(fs::exists(dir / "MESH"));
  for (const char* name : {"mesh.vtu", "case", "pflotran", "mesh.exo"}) EXPECT_FALSE(fs::exists(dir / name)) << name;
  try {
    write_volume_mesh(mesh, dir.path(), {"tough", "gmsh"});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Usage);
    EXPECT_NE(e.message().find("'gmsh'"), std::string::npos);
  }
  EXPECT_TRUE(fs::exists(dir / "MESH"));  // nothing removed before the error
}

}  // namespace
}  // namespace vorocrust
