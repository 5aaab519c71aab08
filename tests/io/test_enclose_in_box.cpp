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

TEST(EncloseInBox, ASheetInItsBoxHoldsItsBoxAndNeedsNoOther) {
  // A run's smoothed surface is the sheet in its box again; smoothing may split the box's sides.
  const SurfaceMesh sheet = one_triangle_sheet();
  EXPECT_FALSE(holds_its_box(sheet));
  SurfaceMesh boxed = enclose_in_box(sheet, default_box(sheet));
  EXPECT_TRUE(holds_its_box(boxed));
  const Index last = static_cast<Index>(boxed.num_faces() - 1);
  const Triangle t = boxed.triangles[last];
  const auto centre = static_cast<Index>(boxed.vertices.size());
  boxed.vertices.push_back((boxed.vertices[t[0]] + boxed.vertices[t[1]] + boxed.vertices[t[2]]) / 3);
  boxed.triangles[last] = {t[0], t[1], centre};
  boxed.add_triangle({t[1], t[2], centre}, boxed.face_group[last]);
  boxed.add_triangle({t[2], t[0], centre}, boxed.face_group[last]);
  EXPECT_TRUE(holds_its_box(boxed));
  // A box missing a side is no box: the sheet goes in one of its own.
  boxed.triangles.erase(boxed.triangles.begin() + last);
  boxed.face_group.erase(boxed.face_group.begin() + last);
  boxed.face_line.erase(boxed.face_line.begin() + last);
  boxed.face_regions.erase(boxed.face_regions.begin() + last);
  EXPECT_FALSE(holds_its_box(boxed));
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
