// SurfaceMesh <-> OpenMesh TriMesh both ways, and a clear refusal where OpenMesh would drop a face.
#include <gtest/gtest.h>

#include "test_support.hpp"
#include "vorocrust/openmesh.hpp"
#include "vorocrust/read_mesh.hpp"

namespace vorocrust {
namespace {

TEST(OpenMeshConversion, ManifoldMeshRoundTripsExactly) {
  const SurfaceMesh bunny = read_mesh(test::model("igl_bunny.off"));
  const OpenMeshTriMesh om = to_openmesh(bunny);
  EXPECT_EQ(om.n_vertices(), bunny.num_vertices());
  EXPECT_EQ(om.n_faces(), bunny.num_faces());
  const SurfaceMesh back = from_openmesh(om);
  ASSERT_EQ(back.num_faces(), bunny.num_faces());
  for (std::size_t f = 0; f < bunny.num_faces(); ++f) {
    // OpenMesh may start a face at another corner; the cyclic order must be the same.
    const Triangle& a = bunny.triangles[f];
    const Triangle& b = back.triangles[f];
    const bool same = (a == b) || (a == Triangle{b[1], b[2], b[0]}) || (a == Triangle{b[2], b[0], b[1]});
    ASSERT_TRUE(same) << "face " << f;
  }
  EXPECT_EQ(back.vertices, bunny.vertices);
  EXPECT_EQ(back.face_group.size(), back.num_faces());
}

TEST(OpenMeshConversion, NonManifoldEdgeIsRefusedNamingTheFace) {
  const SurfaceMesh box = read_mesh(test::model("sandia_non_manifold_box.obj"));
  try {
    (void)to_openmesh(box);
    FAIL() << "OpenMesh cannot hold a non-manifold edge; the conversion must say so";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::InvalidGeometry);
    EXPECT_TRUE(e.where().face.has_value());
    EXPECT_NE(std::string(e.what()).find("sandia_non_manifold_box.obj line"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vorocrust
