// Counts and measures of known shapes.
#include <gtest/gtest.h>

#include "test_support.hpp"
#include "vorocrust/mesh_info.hpp"
#include "vorocrust/read_mesh.hpp"

namespace vorocrust {
namespace {

TEST(MeshInfo, UnitBox) {
  const MeshInfo info = mesh_info(read_mesh(test::model("sandia_OneBox.obj")));
  EXPECT_EQ(info.edges, 18u);
  ASSERT_EQ(info.components.size(), 1u);
  EXPECT_EQ(info.genus, 0);
  ASSERT_TRUE(info.components[0].volume.has_value());
  // The file's faces point inward, so the signed volume is negative.
  EXPECT_NEAR(*info.components[0].volume, -info.bounding_box.volume(), 1e-12);
  EXPECT_NEAR(info.area, 2 * (info.bounding_box.sizes().x() * info.bounding_box.sizes().y() +
                              info.bounding_box.sizes().y() * info.bounding_box.sizes().z() +
                              info.bounding_box.sizes().z() * info.bounding_box.sizes().x()), 1e-12);
}

TEST(MeshInfo, TwoCubesSharingAnEdgeAreOneComponentWithoutVolume) {
  const MeshInfo info = mesh_info(read_mesh(test::model("cgal_cubes_edge_contact.off")));
  ASSERT_EQ(info.components.size(), 1u);
  EXPECT_EQ(info.non_manifold_edges, 1u);
  EXPECT_FALSE(info.components[0].manifold());
  EXPECT_FALSE(info.components[0].volume.has_value());
  EXPECT_FALSE(info.genus.has_value());
}

TEST(MeshInfo, OpenSurfaceHasBoundaryButNoGenus) {
  const MeshInfo info = mesh_info(read_mesh(test::model("gmsh_terrain.stl")));
  EXPECT_EQ(info.boundary_edges, 126u);
  EXPECT_FALSE(info.components[0].closed());
  EXPECT_FALSE(info.genus.has_value());
}

TEST(MeshInfo, NestedShellsEachHaveAVolume) {
  const MeshInfo info = mesh_info(read_mesh(test::model("openmeeg_HeadNNb3.obj")));
  ASSERT_EQ(info.components.size(), 5u);
  for (const ComponentInfo& c : info.components) {
    ASSERT_TRUE(c.volume.has_value());
    EXPECT_NE(*c.volume, 0);  // the file's shells point inward: negative, as written
  }
}

}  // namespace
}  // namespace vorocrust
