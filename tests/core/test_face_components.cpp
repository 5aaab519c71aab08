// Components and their counts, which mesh_info and the surface topology both stand on.
#include <gtest/gtest.h>

#include "core/face_components.hpp"
#include "test_support.hpp"
#include "vorocrust/read_mesh.hpp"

namespace vorocrust {
namespace {

// Two fans that meet only at vertex 0, their faces interleaved in the file.
SurfaceMesh bowtie() {
  SurfaceMesh m;
  m.groups.push_back({"bowtie", ""});
  m.vertices = {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(-1, 0, 0), Point(-1, -1, 0), Point(0, 1, 0),
                Point(0, -1, 0)};
  for (Triangle t : {Triangle{0, 1, 2}, Triangle{0, 3, 4}, Triangle{0, 2, 5}, Triangle{0, 4, 6}}) m.add_triangle(t, 0);
  return m;
}

TEST(FaceComponents, ASharedVertexCountsOnceInEachComponent) {
  const SurfaceMesh m = bowtie();
  const FaceComponents found = face_components(m, build_edge_topology(m));
  ASSERT_EQ(found.components.size(), 2u);
  EXPECT_EQ(found.of_face, (std::vector<Index>{0, 1, 0, 1}));
  EXPECT_EQ(found.faces[0], (std::vector<Index>{0, 2}));
  for (const ComponentInfo& c : found.components) {
    EXPECT_EQ(c.faces, 2u);
    EXPECT_EQ(c.vertices, 4u);
    EXPECT_EQ(c.edges, 5u);
    EXPECT_EQ(c.boundary_edges, 4u);
    EXPECT_EQ(c.euler_characteristic(), 1);  // a disc
  }
}

TEST(FaceComponents, NumberedByTheirSmallestFace) {
  const SurfaceMesh m = read_mesh(test::model("cgal_bones.off"));
  const FaceComponents found = face_components(m, build_edge_topology(m));
  ASSERT_EQ(found.components.size(), 26u);
  for (std::size_t c = 1; c < found.faces.size(); ++c) EXPECT_LT(found.faces[c - 1][0], found.faces[c][0]);
  for (const ComponentInfo& c : found.components) EXPECT_EQ(c.euler_characteristic(), 2);
}

}  // namespace
}  // namespace vorocrust
