// Merging parts into one model: groups named after their parts, vertices shared across parts
// only where coordinates are exactly equal, region labels kept by name.
#include <gtest/gtest.h>

#include <vector>

#include "test_support.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/merge_surfaces.hpp"
#include "vorocrust/read_mesh.hpp"
#include "vorocrust/surface_from_arrays.hpp"

namespace vorocrust {
namespace {

SurfaceMesh triangles(std::vector<double> coordinates, std::vector<std::int64_t> corners, const std::string& name) {
  return surface_from_arrays(coordinates, corners, name);
}

TEST(MergeSurfaces, SharesExactlyEqualVerticesAcrossPartsOnly) {
  // Part a repeats its vertex (0,1,0); part b's first two corners are a's first two.
  const std::vector<NamedSurface> parts{
      {"a", triangles({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0}, {0, 1, 2, 0, 1, 3}, "a source")},
      {"b", triangles({0, 0, 0, 1, 0, 0, 0, 0, 1}, {0, 1, 2}, "b source")}};
  const SurfaceMesh m = merge_surfaces(parts);
  EXPECT_EQ(m.num_vertices(), 5u);
  EXPECT_EQ(m.triangles, (std::vector<Triangle>{{0, 1, 2}, {0, 1, 3}, {0, 1, 4}}));
  ASSERT_EQ(m.groups.size(), 2u);
  EXPECT_EQ(m.groups[0].name, "a");
  EXPECT_EQ(m.groups[1].name, "b");
  EXPECT_EQ(m.groups[1].source_file, "b source");
  EXPECT_EQ(m.face_group, (std::vector<Index>{0, 0, 1}));
  EXPECT_EQ(describe_face(m, 2), "face 2 (b source)");
}

TEST(MergeSurfaces, NamesTheGroupsOfAPartWithSeveral) {
  const SurfaceMesh head = read_mesh(test::model("openmeeg_HeadNNa1.obj"));  // groups cut, north, ...
  ASSERT_GT(head.groups.size(), 1u);
  const std::vector<NamedSurface> parts{{"box", triangles({0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 1, 2}, "box")},
                                        {"head", head}};
  const SurfaceMesh m = merge_surfaces(parts);
  ASSERT_EQ(m.groups.size(), 1 + head.groups.size());
  for (std::size_t g = 0; g < head.groups.size(); ++g) {
    EXPECT_EQ(m.groups[1 + g].name, "head/" + head.groups[g].name);
    EXPECT_EQ(m.groups[1 + g].source_file, head.groups[g].source_file);
  }
  EXPECT_EQ(m.num_faces(), 1 + head.num_faces());
}

TEST(MergeSurfaces, KeepsRegionLabelsByName) {
  SurfaceMesh steel = triangles({0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 1, 2}, "steel");
  steel.region_names = {"outside", "steel"};
  steel.face_regions = {{1, 0}};
  SurfaceMesh air = triangles({0, 0, 2, 1, 0, 2, 0, 1, 2}, {0, 1, 2}, "air");
  air.region_names = {"air", "steel"};
  air.face_regions = {{0, RegionPair::kUnknownRegion}};
  const std::vector<NamedSurface> parts{{"plain", triangles({0, 0, 5, 1, 0, 5, 0, 1, 5}, {0, 1, 2}, "plain")},
                                        {"steel", steel}, {"air", air}};
  const SurfaceMesh m = merge_surfaces(parts);
  ASSERT_TRUE(m.has_regions());
  // Names in order of first use: steel's back, steel's front, air's back.
  EXPECT_EQ(m.region_names, (std::vector<std::string>{"steel", "outside", "air"}));
  EXPECT_EQ(m.face_regions, (std::vector<RegionPair>{{}, {0, 1}, {2, RegionPair::kUnknownRegion}}));
}

TEST(MergeSurfaces, NothingToMergeIsAUsageError) {
  try {
    merge_surfaces({});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Usage);
    EXPECT_STREQ(e.what(), "no surface to merge");
  }
}

}  // namespace
}  // namespace vorocrust
