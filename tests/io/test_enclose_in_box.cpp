// The box around open sheets (paper Figure 17).
#include <gtest/gtest.h>

#include <numeric>

#include "core/surface_measures.hpp"
#include "io/enclose_in_box.hpp"
#include "vorocrust/regions.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust {
namespace {

SurfaceMesh one_triangle_sheet() {
  SurfaceMesh sheet;
  sheet.vertices = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0.5)};
  sheet.groups.push_back({"sheet", ""});
  sheet.add_triangle({0, 1, 2}, 0);
  return sheet;
}

std::vector<Index> faces_from(std::size_t first, std::size_t end) {
  std::vector<Index> faces(end - first);
  std::iota(faces.begin(), faces.end(), static_cast<Index>(first));
  return faces;
}

TEST(EncloseInBox, AnOpenSheetNeedsABoxAClosedSurfaceNone) {
  EXPECT_TRUE(needs_box(one_triangle_sheet()));
  SurfaceMesh tetrahedron;
  tetrahedron.vertices = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)};
  tetrahedron.groups.push_back({"t", ""});
  for (const Triangle& t : {Triangle{0, 2, 1}, Triangle{0, 1, 3}, Triangle{1, 2, 3}, Triangle{0, 3, 2}}) {
    tetrahedron.add_triangle(t, 0);
  }
  EXPECT_FALSE(needs_box(tetrahedron));
}

TEST(EncloseInBox, TheDefaultBoxLeavesATenthOfTheDiagonalOnEverySide) {
  const geometry::Box box = default_box(one_triangle_sheet());
  const double margin = 0.1 * Point(1, 1, 0.5).norm();
  EXPECT_TRUE(box.lo.isApprox(Point(-margin, -margin, -margin)));
  EXPECT_TRUE(box.hi.isApprox(Point(1 + margin, 1 + margin, 0.5 + margin)));
}

TEST(EncloseInBox, AnUnlabelledSheetIsDomainOnBothSidesInsideAnOutwardBox) {
  const SurfaceMesh sheet = one_triangle_sheet();
  const geometry::Box box{Point(-1, -2, -3), Point(2, 3, 4)};
  const SurfaceMesh boxed = enclose_in_box(sheet, box);
  ASSERT_EQ(boxed.num_faces(), 13u);
  EXPECT_EQ(boxed.num_vertices(), 11u);
  ASSERT_EQ(boxed.region_names, (std::vector<std::string>{"outside", "domain"}));
  EXPECT_EQ(boxed.face_regions[0], RegionPair{});  // left to the region stage
  SurfaceMesh labelled = boxed;
  label_regions(labelled);
  EXPECT_EQ(labelled.face_regions[0], (RegionPair{1, 1}));
  for (std::size_t f = 1; f < 13; ++f) {
    EXPECT_EQ(boxed.face_regions[f], (RegionPair{1, 0})) << "face " << f;
    EXPECT_EQ(boxed.groups[boxed.face_group[f]].name, "box");
  }
  // Outward normals: the box faces enclose its volume with a positive sign.
  EXPECT_NEAR(enclosed_volume(boxed, faces_from(1, 13)), 3.0 * 5.0 * 7.0, 1e-12);
  EXPECT_NEAR(surface_area(boxed, faces_from(1, 13)), 2 * (3.0 * 5 + 5.0 * 7 + 3.0 * 7), 1e-12);
}

TEST(EncloseInBox, ALabelledModelKeepsItsMaterialsAndItsOutsideBecomesDomain) {
  SurfaceMesh labelled = one_triangle_sheet();
  labelled.region_names = {"air", "rock"};
  labelled.face_regions = {RegionPair{1, 0}};
  const SurfaceMesh boxed = enclose_in_box(labelled, geometry::Box{Point(-1, -1, -1), Point(2, 2, 2)});
  ASSERT_EQ(boxed.region_names, (std::vector<std::string>{"air", "rock", "domain"}));
  EXPECT_EQ(boxed.face_regions[0], (RegionPair{1, 2}));
  EXPECT_EQ(boxed.face_regions[1], (RegionPair{2, 0}));
}

TEST(EncloseInBox, ABoxThatDoesNotHoldTheModelIsRefusedNamingTheVertex) {
  try {
    enclose_in_box(one_triangle_sheet(), geometry::Box{Point(-1, -1, -1), Point(0.5, 2, 2)});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::InvalidGeometry);
    EXPECT_NE(std::string(e.what()).find("vertex 1 at (1, 0, 0) does not lie inside the box"), std::string::npos) << e.what();
  }
  EXPECT_THROW(enclose_in_box(one_triangle_sheet(), geometry::Box{Point(2, -1, -1), Point(1, 2, 2)}), Error);
}

}  // namespace
}  // namespace vorocrust
