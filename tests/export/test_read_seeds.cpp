// seeds.csv read back: what write_seeds_csv writes comes back exactly, so the mesh rebuilt from
// the file is the mesh of the seeds; broken files are errors naming their file and line.
#include <gtest/gtest.h>

#include <fstream>

#include "cells/seed_sets.hpp"
#include "test_support.hpp"
#include "vorocrust/cells.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/seeds.hpp"

namespace vorocrust {
namespace {

TEST(ReadSeeds, RoundTripGivesTheSameMesh) {
  auto seeds = test::lattice_seeds(9, 0.3, test::ball_region(Point(4, 4, 4), 3.2), 11);
  seeds[5].kind = SeedKind::Surface;
  seeds[6].radius = 0.123456789012345678;
  const test::TempDir dir("seeds");
  write_seeds_csv(seeds, dir / "seeds.csv");
  const std::vector<Seed> read = read_seeds_csv(dir / "seeds.csv");
  ASSERT_EQ(read.size(), seeds.size());
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    ASSERT_EQ(read[s].position, seeds[s].position);
    ASSERT_EQ(read[s].region, seeds[s].region);
    ASSERT_EQ(read[s].radius, seeds[s].radius);
    ASSERT_EQ(read[s].kind, seeds[s].kind);
  }
  const VoronoiMesh a = compute_cells(seeds), b = compute_cells(read);
  EXPECT_EQ(a.points, b.points);
  ASSERT_EQ(a.faces.size(), b.faces.size());
  for (std::size_t f = 0; f < a.faces.size(); ++f) EXPECT_EQ(a.faces[f].points, b.faces[f].points);
}

TEST(ReadSeeds, BrokenFilesNameFileAndLine) {
  const test::TempDir dir("bad-seeds");
  const std::string header = "x,y,z,label,radius,kind\n";
  const std::string good = "0,0,0,1,0.5,interior\n";
  const struct {
    std::string text;
    std::size_t line;
    std::string phrase;
  } cases[] = {
      {"", 0, "empty: no header line"},
      {"x,y,z\n" + good, 1, "the header line is not x,y,z,label,radius,kind"},
      {header + good + "1,2,3,1,0.5\n", 3, "6 comma-separated fields"},
      {header + "\n" + good + "1,2,3,1,0.5,interior,7\n", 4, "this line 7"},
      {header + "1,nan,3,1,0.5,interior\n", 2, "y is not a finite number: 'nan'"},
      {header + "1,2,abc,1,0.5,interior\n", 2, "z is not a finite number: 'abc'"},
      {header + "1,2,3,1.5,0.5,interior\n", 2, "label is not a 32-bit integer: '1.5'"},
      {header + "1,2,3,99999999999,0.5,interior\n", 2, "label is not a 32-bit integer"},
      {header + "1,2,3,1,-1,interior\n", 2, "radius is not a finite number >= 0"},
      {header + good + good + "1,2,3,1,0.5,inside\n", 4, "kind is not surface, interior, outside, cap or repair: 'inside'"},
  };
  int k = 0;
  for (const auto& c : cases) {
    const auto path = dir / ("bad" + std::to_string(k++) + ".csv");
    std::ofstream(path) << c.text;
    try {
      read_seeds_csv(path);
      ADD_FAILURE() << "no error for: " << c.text;
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::UnreadableInput);
      EXPECT_EQ(e.where().file, path.string());
      EXPECT_EQ(e.where().line, c.line) << e.what();
      EXPECT_NE(e.message().find(c.phrase), std::string::npos) << e.what();
      if (c.line) {
        EXPECT_NE(std::string(e.what()).find(path.string() + ":" + std::to_string(c.line) + ": "), std::string::npos);
      }
    }
  }
  try {
    read_seeds_csv(dir / "missing.csv");
    ADD_FAILURE() << "no error for a missing file";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::UnreadableInput);
  }
}

}  // namespace
}  // namespace vorocrust
