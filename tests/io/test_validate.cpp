// Validation on inputs that read fine but are wrong: each problem found, named and, for
// orientation, repaired.
#include <gtest/gtest.h>

#include "core/surface_measures.hpp"
#include "test_support.hpp"
#include "vorocrust/read_mesh.hpp"
#include "vorocrust/validate.hpp"

namespace vorocrust {
namespace {

SurfaceMesh invalid(const std::string& name) { return read_mesh(test::data("invalid/" + name)); }

std::vector<Index> all_faces(const SurfaceMesh& m) {
  std::vector<Index> faces(m.num_faces());
  for (Index f = 0; f < faces.size(); ++f) faces[f] = f;
  return faces;
}

TEST(Validate, CleanCubeHasNoFindings) {
  SurfaceMesh m = invalid("cube.off");
  const ValidationReport r = validate(m);
  EXPECT_TRUE(r.findings.empty()) << r.findings.front().message;
  EXPECT_FALSE(r.has_errors());
}

TEST(Validate, PiercingTriangleIsASelfIntersectionWithItsPairs) {
  SurfaceMesh m = invalid("cube_pierced.off");
  const ValidationReport r = validate(m);
  ASSERT_TRUE(r.has_errors());
  const Finding* f = r.find("self-intersection");
  ASSERT_NE(f, nullptr);
  // The triangle (face 12) crosses the bottom and the top of the cube on their diagonals, so it
  // meets both triangles of each.
  EXPECT_EQ(f->count, 4u);
  for (const auto& [a, b] : f->face_pairs) {
    EXPECT_EQ(b, 12u);
    EXPECT_TRUE(a <= 3) << a;  // faces 0,1 are the bottom, 2,3 the top
  }
  EXPECT_NE(f->message.find("face 12 (cube_pierced.off line 26)"), std::string::npos) << f->message;
  ValidationOptions skip;
  skip.check_self_intersections = false;
  SurfaceMesh again = invalid("cube_pierced.off");
  EXPECT_EQ(validate(again, skip).find("self-intersection"), nullptr);
}

TEST(Validate, DuplicateFaceIsAnErrorNamingBoth) {
  SurfaceMesh m = invalid("cube_duplicate_face.off");
  const ValidationReport r = validate(m);
  const Finding* f = r.find("duplicate-face");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->severity, Finding::Severity::Error);
  ASSERT_EQ(f->face_pairs.size(), 1u);
  EXPECT_EQ(f->face_pairs[0], (std::pair<std::size_t, std::size_t>{3, 12}));
}

TEST(Validate, ZeroAreaFaceIsFoundExactly) {
  SurfaceMesh m = invalid("cube_zero_area.off");
  const ValidationReport r = validate(m);
  const Finding* f = r.find("zero-area-face");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->faces, (std::vector<std::size_t>{12}));
}

TEST(Validate, FlippedFaceIsTurnedBackAndReported) {
  SurfaceMesh m = invalid("cube_flipped_face.off");
  const SurfaceMesh reference = invalid("cube.off");
  const ValidationReport r = validate(m);
  const Finding* f = r.find("inconsistent-orientation");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->severity, Finding::Severity::Fixed);
  EXPECT_EQ(f->faces, (std::vector<std::size_t>{5}));
  EXPECT_FALSE(r.has_errors());
  EXPECT_NEAR(enclosed_volume(m, all_faces(m)), 1.0, 1e-12);
  EXPECT_EQ(m.triangles[5][0], reference.triangles[5][0]);
}

TEST(Validate, InsideOutShellIsTurnedOutward) {
  SurfaceMesh m = invalid("cube_inside_out.off");
  EXPECT_NEAR(enclosed_volume(m, all_faces(m)), -1.0, 1e-12);
  const ValidationReport r = validate(m);
  ASSERT_NE(r.find("inward-shell"), nullptr);
  EXPECT_EQ(r.find("inconsistent-orientation"), nullptr);  // consistent, just inward
  EXPECT_NEAR(enclosed_volume(m, all_faces(m)), 1.0, 1e-12);
}

TEST(Validate, FlippingSwapsRegionLabels) {
  SurfaceMesh m = invalid("cube_flipped_face.off");
  m.region_names = {"in", "out"};
  m.face_regions.assign(m.num_faces(), RegionPair{0, 1});
  m.face_regions[5] = RegionPair{1, 0};  // labelled as read: its normal points inward
  (void)validate(m);
  for (const RegionPair& r : m.face_regions) EXPECT_EQ(r, (RegionPair{0, 1}));
}

TEST(Validate, FacesTwoPartsBothHoldAreAnError) {
  // Merging keeps one copy of a face two files share; a mesh put together otherwise may hold both.
  SurfaceMesh m = read_mesh(test::data("invalid/cube.off"));
  m.groups.push_back({"twin", "twin.off"});
  const std::size_t n = m.num_faces();
  for (std::size_t f = 0; f < n; ++f) {
    Triangle t = m.triangles[f];
    std::swap(t[1], t[2]);
    m.add_triangle(t, 1);
  }
  const ValidationReport r = validate(m, {.fix_orientation = false});
  const Finding* shared = r.find("shared-face");
  ASSERT_NE(shared, nullptr);
  EXPECT_EQ(shared->severity, Finding::Severity::Error);
  EXPECT_EQ(shared->count, 12u);
  EXPECT_NE(shared->message.find("merge_surfaces"), std::string::npos);
  EXPECT_EQ(r.find("duplicate-face"), nullptr);
}

TEST(Validate, SharedModelsHaveNoSelfIntersections) {
  for (const char* name : {"cgal_joint.off", "sandia_non_manifold_box.obj", "openmeeg_HeadNNc3.obj",
                           "cgal_cubes_edge_contact.off", "netgen_hinge.stl"}) {
    SurfaceMesh m = read_mesh(test::model(name));
    const ValidationReport r = validate(m);
    EXPECT_FALSE(r.has_errors()) << name << ": " << (r.findings.empty() ? "" : r.findings.front().message);
  }
}

}  // namespace
}  // namespace vorocrust
