// Read, write, read again: every writer gives back the same mesh (binary STL through float).
#include <gtest/gtest.h>

#include "test_support.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/read_mesh.hpp"
#include "vorocrust/write_mesh.hpp"

namespace vorocrust {
namespace {

struct Case {
  const char* model;
  const char* extension;
  bool ascii;
};

std::ostream& operator<<(std::ostream& os, const Case& c) {
  return os << c.model << " as " << c.extension << (c.ascii ? " ascii" : "");
}

class RoundTrip : public ::testing::TestWithParam<Case> {};

TEST_P(RoundTrip, GivesBackTheSameMesh) {
  const Case& c = GetParam();
  const SurfaceMesh original = read_mesh(test::model(c.model));
  test::TempDir dir("roundtrip");
  const auto path = dir / (std::string("copy") + c.extension);
  write_mesh(original, path, {.ascii = c.ascii});
  const SurfaceMesh copy = read_mesh(path);
  ASSERT_EQ(copy.num_faces(), original.num_faces());
  const bool is_stl = std::string(c.extension) == ".stl";
  if (!is_stl) {
    // OFF, OBJ and PLY keep the vertex list and the triangles exactly.
    EXPECT_EQ(copy.triangles, original.triangles);
    ASSERT_EQ(copy.num_vertices(), original.num_vertices());
    for (std::size_t v = 0; v < original.num_vertices(); ++v) ASSERT_EQ(copy.vertices[v], original.vertices[v]) << v;
  } else {
    // STL keeps each face's corners in order: exactly as text, rounded to float as binary.
    for (std::size_t f = 0; f < original.num_faces(); ++f) {
      for (int k = 0; k < 3; ++k) {
        const Point& p = original.vertices[original.triangles[f][k]];
        const Point& q = copy.vertices[copy.triangles[f][k]];
        for (int i = 0; i < 3; ++i) {
          if (c.ascii) {
            ASSERT_EQ(q[i], p[i]) << "face " << f;
          } else {
            ASSERT_EQ(static_cast<float>(q[i]), static_cast<float>(p[i])) << "face " << f;
            ASSERT_EQ(q[i], static_cast<double>(static_cast<float>(q[i]))) << "binary STL holds floats";
          }
        }
      }
    }
  }
  EXPECT_EQ(copy.has_regions(), original.has_regions());
  if (original.has_regions() && !is_stl) {
    EXPECT_EQ(copy.face_regions, original.face_regions);
    EXPECT_EQ(copy.region_names, original.region_names);
  }
  // Nothing is left behind but the written file.
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++entries;
  EXPECT_EQ(entries, 1u);
}

INSTANTIATE_TEST_SUITE_P(Writers, RoundTrip,
                         ::testing::Values(Case{"cgal_joint.off", ".off", true}, Case{"cgal_joint.off", ".obj", true},
                                           Case{"cgal_joint.off", ".ply", false}, Case{"cgal_joint.off", ".ply", true},
                                           Case{"cgal_joint.off", ".stl", false}, Case{"cgal_joint.off", ".stl", true},
                                           Case{"netgen_hinge.stl", ".stl", false},
                                           Case{"openmeeg_HeadNNa1.obj", ".ply", false},
                                           Case{"sandia_non_manifold_box.obj", ".obj", true},
                                           Case{"sandia_non_manifold_box.obj", ".ply", false}));

TEST(RoundTrip, RegionLabelsSurviveObjAndPly) {
  SurfaceMesh m = read_mesh(test::model("sandia_OneBox.obj"));
  m.region_names = {"rock", "air"};
  m.face_regions.assign(m.num_faces(), RegionPair{0, 1});
  m.face_regions[3] = RegionPair{1, 0};
  test::TempDir dir("roundtrip");
  for (const char* name : {"box.ply", "box.obj"}) {
    write_mesh(m, dir / name);
    const SurfaceMesh copy = read_mesh(dir / name);
    ASSERT_TRUE(copy.has_regions()) << name;
    EXPECT_EQ(copy.region_names[copy.face_regions[0].back], "rock") << name;
    EXPECT_EQ(copy.region_names[copy.face_regions[0].front], "air") << name;
    std::size_t reversed = 0;
    for (const RegionPair& r : copy.face_regions) reversed += copy.region_names[r.back] == "air";
    EXPECT_EQ(reversed, 1u) << name;
  }
}

TEST(WriteMesh, FailedWriteLeavesNoFile) {
  const SurfaceMesh m = read_mesh(test::model("sandia_OneBox.obj"));
  test::TempDir dir("roundtrip");
  EXPECT_THROW(write_mesh(m, dir / "missing-folder" / "x.off"), Error);
  EXPECT_THROW(write_mesh(m, dir / "x.unknown"), Error);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace vorocrust
