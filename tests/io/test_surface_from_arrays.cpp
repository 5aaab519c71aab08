// Building an input surface from arrays: the same mesh a reader gives for the same data, and
// every bad array refused with a message naming the source and the element.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "test_support.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/read_mesh.hpp"
#include "vorocrust/surface_from_arrays.hpp"

namespace vorocrust {
namespace {

// The corners and triangles of a mesh as flat arrays, as NumPy would hand them over.
struct Arrays {
  std::vector<double> coordinates;
  std::vector<std::int64_t> corners;
};

Arrays arrays_of(const SurfaceMesh& mesh) {
  Arrays a;
  for (const Point& p : mesh.vertices) a.coordinates.insert(a.coordinates.end(), {p.x(), p.y(), p.z()});
  for (const Triangle& t : mesh.triangles) a.corners.insert(a.corners.end(), {t[0], t[1], t[2]});
  return a;
}

Arrays tetrahedron() {
  return {{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}};
}

// The message of the Error `make` throws, with its kind checked.
template <class Make>
std::string error_of(Error::Kind kind, Make make) {
  try {
    make();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), kind) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return {};
}

TEST(SurfaceFromArrays, KeepsEveryVertexAndTriangleOfAModel) {
  const SurfaceMesh read = read_mesh(test::model("cgal_joint.off"));
  const Arrays a = arrays_of(read);
  const SurfaceMesh m = surface_from_arrays(a.coordinates, a.corners, "joint arrays");
  EXPECT_EQ(m.vertices, read.vertices);
  EXPECT_EQ(m.triangles, read.triangles);
  ASSERT_EQ(m.groups.size(), 1u);
  EXPECT_EQ(m.groups[0].name, "joint arrays");
  EXPECT_EQ(m.face_group, std::vector<Index>(read.num_faces(), 0));
  EXPECT_EQ(m.face_line, std::vector<std::uint32_t>(read.num_faces(), 0));
  EXPECT_FALSE(m.has_regions());
  EXPECT_EQ(describe_face(m, 5), "face 5 (joint arrays)");
}

TEST(SurfaceFromArrays, RefusesArraysThatAreNoMesh) {
  Arrays a = tetrahedron();
  EXPECT_EQ(error_of(Error::Kind::Usage, [&] { surface_from_arrays({a.coordinates.data(), 11}, a.corners, "Box"); }),
            "Box: the vertex array holds 11 numbers, not three (x, y, z) per vertex");
  EXPECT_EQ(error_of(Error::Kind::Usage, [&] { surface_from_arrays(a.coordinates, {a.corners.data(), 10}, "Box"); }),
            "Box: the triangle array holds 10 indices, not three per triangle");
  EXPECT_EQ(error_of(Error::Kind::InvalidGeometry, [&] { surface_from_arrays(a.coordinates, {}, "Box"); }),
            "Box: empty mesh: no triangles");

  a.corners[7] = 4;
  try {
    surface_from_arrays(a.coordinates, a.corners, "Box");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::UnreadableInput);
    EXPECT_STREQ(e.what(), "Box: triangle 2 has vertex index 4, out of range: there are 4 vertices (0-based)");
    EXPECT_EQ(e.where().face, 2u);
  }
  a.corners[7] = -1;
  EXPECT_EQ(error_of(Error::Kind::UnreadableInput, [&] { surface_from_arrays(a.coordinates, a.corners, "Box"); }),
            "Box: triangle 2 has vertex index -1, out of range: there are 4 vertices (0-based)");
  a.corners[7] = 0;
  EXPECT_EQ(error_of(Error::Kind::InvalidGeometry, [&] { surface_from_arrays(a.coordinates, a.corners, "Box"); }),
            "Box: face repeats vertex 0: a triangle needs three distinct corners");

  a = tetrahedron();
  a.coordinates[10] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(error_of(Error::Kind::InvalidGeometry, [&] { surface_from_arrays(a.coordinates, a.corners, "Box"); }),
            "Box: vertex 3 has a coordinate that is not a finite number (NaN or infinity)");
  a.coordinates[10] = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(error_of(Error::Kind::InvalidGeometry, [&] { surface_from_arrays(a.coordinates, a.corners, "Box"); }),
            "Box: vertex 3 has a coordinate that is not a finite number (NaN or infinity)");
}

}  // namespace
}  // namespace vorocrust
