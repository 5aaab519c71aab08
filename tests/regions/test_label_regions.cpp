// The regions of space a surface cuts out: wedges around edges, shells, nesting, given labels.
#include <gtest/gtest.h>

#include "regions/radial_order.hpp"
#include "regions/region_labels_hold.hpp"
#include "surface_builder.hpp"
#include "test_support.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/merge_surfaces.hpp"
#include "vorocrust/read_mesh.hpp"
#include "vorocrust/regions.hpp"
#include "vorocrust/surface_from_arrays.hpp"
#include "vorocrust/validate.hpp"

namespace vorocrust {
namespace {

using Builder = test::SurfaceBuilder;

std::size_t faces_with(const SurfaceMesh& m, RegionPair pair) {
  std::size_t n = 0;
  for (const RegionPair& r : m.face_regions) n += r == pair;
  return n;
}

TEST(RadialOrder, FacesAroundAnEdgeComeInTheOrderOfTheirAngle) {
  // Edge along z from (0,0,0) to (0,0,1); third corners at 0, 90, 180 and 270 degrees about +z.
  SurfaceMesh m;
  m.vertices = {Point(0, 0, 0), Point(0, 0, 1), Point(1, 0, 0), Point(0, 1, 0), Point(-1, 0, 0), Point(0, -1, 0)};
  m.groups.push_back({"g", ""});
  m.add_triangle({0, 1, 2}, 0);  // 0 degrees
  m.add_triangle({1, 0, 4}, 0);  // 180 degrees, the other way round
  m.add_triangle({0, 1, 5}, 0);  // 270 degrees
  m.add_triangle({0, 1, 3}, 0);  // 90 degrees
  const std::vector<Index> faces{0, 1, 2, 3};
  EXPECT_EQ(regions::faces_around_edge(m, 0, 1, faces), (std::vector<Index>{0, 3, 1, 2}));
  const std::vector<Index> from_another{2, 0, 1, 3};  // starting at 270: 270, 0, 90, 180
  EXPECT_EQ(regions::faces_around_edge(m, 0, 1, from_another), (std::vector<Index>{2, 0, 3, 1}));
}

TEST(RadialOrder, NearlyFlatFacesAreOrderedExactly) {
  // Third corners 2^-40 apart in angle near the reference half-plane: the order comes from
  // exact orientation tests, not from rounded angles.
  const double tiny = std::ldexp(1.0, -40);
  SurfaceMesh m;
  m.vertices = {Point(0, 0, 0), Point(0, 0, 1), Point(1, 0, 0), Point(1, tiny, 0), Point(1, 2 * tiny, 0), Point(0, 1, 0)};
  m.groups.push_back({"g", ""});
  for (Index c : {Index{4}, Index{2}, Index{5}, Index{3}}) m.add_triangle({0, 1, c}, 0);
  const std::vector<Index> faces{1, 0, 2, 3};  // from corner 2 (angle 0)
  EXPECT_EQ(regions::faces_around_edge(m, 0, 1, faces), (std::vector<Index>{1, 3, 0, 2}));
}

TEST(LabelRegions, OneClosedShellBoundsTheOneRegionInside) {
  Builder b;
  b.box(Point(0, 0, 0), Point(1, 2, 3));
  const std::vector<RegionSummary> regions = label_regions(b.mesh);
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_EQ(b.mesh.region_names, (std::vector<std::string>{"outside", "inside"}));
  EXPECT_EQ(faces_with(b.mesh, {1, 0}), 12u);
  EXPECT_NEAR(regions[1].volume, 6.0, 1e-12);
  EXPECT_EQ(regions[1].pieces, 1u);
  EXPECT_EQ(regions[0].pieces, 1u);
}

TEST(LabelRegions, OrientationDoesNotMatter) {
  Builder b;
  b.box(Point(0, 0, 0), Point(1, 1, 1));
  for (std::size_t f = 0; f < b.mesh.num_faces(); f += 3) b.mesh.flip(f);
  label_regions(b.mesh);
  for (std::size_t f = 0; f < b.mesh.num_faces(); ++f) {
    EXPECT_EQ(b.mesh.face_regions[f], f % 3 == 0 ? (RegionPair{0, 1}) : (RegionPair{1, 0})) << "face " << f;
  }
}

TEST(LabelRegions, NestedShellsBoundTheSpaceBetweenThem) {
  Builder b;
  b.box(Point(0, 0, 0), Point(3, 3, 3));
  b.box(Point(1, 1, 1), Point(2, 2, 2));
  const std::vector<RegionSummary> regions = label_regions(b.mesh);
  ASSERT_EQ(regions.size(), 3u);
  EXPECT_NEAR(regions[1].volume, 26.0, 1e-12);  // between: 27 - 1
  EXPECT_NEAR(regions[2].volume, 1.0, 1e-12);
  EXPECT_EQ(faces_with(b.mesh, {1, 0}), 12u);  // the outer box
  EXPECT_EQ(faces_with(b.mesh, {2, 1}), 12u);  // the inner one
}

// The labels of nested boxes after their vertices move, as smoothing moves them.
TEST(RegionLabelsHold, OnlyWhileNoShellIsCarriedAcrossAnother) {
  Builder b;
  b.box(Point(0, 0, 0), Point(3, 3, 3));
  b.box(Point(1, 1, 1), Point(2, 2, 2));
  label_regions(b.mesh);
  const SurfaceMesh labelled = b.mesh;
  const auto moved = [&](Index first, Index last, auto&& move) {
    SurfaceMesh m = labelled;
    for (Index v = first; v < last; ++v) m.vertices[v] = move(m.vertices[v]);
    return m;
  };
  EXPECT_TRUE(region_labels_hold(labelled));
  EXPECT_TRUE(region_labels_hold(moved(0, 16, [](const Point& p) -> Point { return p + Point(5, -2, 1); })));
  EXPECT_TRUE(region_labels_hold(moved(8, 16, [](const Point& p) -> Point { return p + Point(0.5, 0, 0); })));
  // The inner box out beside the outer one: its outside, labelled 1, and the outer box's,
  // labelled 0, face one region of space.
  EXPECT_FALSE(region_labels_hold(moved(8, 16, [](const Point& p) -> Point { return p + Point(4, 0, 0); })));
  // The outer box shrunk inside the inner one, crossing nothing: the nesting is turned over.
  EXPECT_FALSE(region_labels_hold(moved(0, 8, [](const Point& p) -> Point { return Point(1.25, 1.25, 1.25) + p / 6; })));
}

TEST(LabelRegions, SolidsSideBySideAndOneInsideAnotherEachGetARegion) {
  Builder b;
  b.box(Point(0, 0, 0), Point(10, 10, 10));
  b.box(Point(1, 1, 1), Point(2, 2, 2));
  b.box(Point(5, 5, 5), Point(7, 7, 7));
  b.box(Point(20, 0, 0), Point(21, 1, 1));  // apart, outside
  const std::vector<RegionSummary> regions = label_regions(b.mesh);
  ASSERT_EQ(regions.size(), 5u);
  EXPECT_NEAR(regions[1].volume, 1000.0 - 1 - 8, 1e-9);
  EXPECT_NEAR(regions[2].volume, 1.0, 1e-12);
  EXPECT_NEAR(regions[3].volume, 8.0, 1e-12);
  EXPECT_NEAR(regions[4].volume, 1.0, 1e-12);
  for (std::size_t f = 12; f < 36; ++f) EXPECT_EQ(b.mesh.face_regions[f].front, 1) << "face " << f;
  for (std::size_t f = 36; f < 48; ++f) EXPECT_EQ(b.mesh.face_regions[f], (RegionPair{4, 0})) << "face " << f;
}

TEST(LabelRegions, AWallSplitsABoxIntoTwoRegionsAcrossNonManifoldEdges) {
  Builder b;
  b.box(Point(0, 0, 0), Point(1, 1, 1), /*skip_high_x=*/true);
  b.box(Point(1, 0, 0), Point(3, 1, 1));  // its low-x side is the wall
  const std::vector<RegionSummary> regions = label_regions(b.mesh);
  ASSERT_EQ(regions.size(), 3u);
  EXPECT_NEAR(regions[1].volume, 1.0, 1e-12);
  EXPECT_NEAR(regions[2].volume, 2.0, 1e-12);
  // The wall (faces 10 and 11, the second box's x = 1 side, normal -x) has region 2 behind it.
  EXPECT_EQ(b.mesh.face_regions[10], (RegionPair{2, 1}));
  EXPECT_EQ(b.mesh.face_regions[11], (RegionPair{2, 1}));
}

TEST(LabelRegions, AFinInsideARegionHasThatRegionOnBothSides) {
  Builder b;
  b.box(Point(0, 0, 0), Point(4, 4, 4));
  b.quad(Point(0.5, 1, 1), Point(0.5, 1, 3), Point(2, 1, 3), Point(2, 1, 1));  // touches nothing
  const std::vector<RegionSummary> regions = label_regions(b.mesh);
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_EQ(b.mesh.face_regions[12], (RegionPair{1, 1}));
  EXPECT_NEAR(regions[1].volume, 64.0, 1e-12);
}

TEST(LabelRegions, CubesTouchingAlongOneEdgeAreTwoRegions) {
  SurfaceMesh m = read_mesh(test::model("cgal_cubes_edge_contact.off"));
  const std::vector<RegionSummary> regions = label_regions(m);
  ASSERT_EQ(regions.size(), 3u);
  EXPECT_NEAR(regions[1].volume, 1.0, 1e-12);
  EXPECT_NEAR(regions[2].volume, 1.0, 1e-12);
}

TEST(LabelRegions, TheSharedNonManifoldModelsSplitIntoTheirRooms) {
  struct Case {
    const char* model;
    std::size_t regions;
    double total;
  };
  for (const Case& c : {Case{"sandia_non_manifold_box.obj", 3, 500.0 * 250 * 100},
                        Case{"sandia_cube_test_02.obj", 4, 4000.0}, Case{"sandia_cube_test_04.obj", 6, 4000.0}}) {
    SurfaceMesh m = read_mesh(test::model(c.model));
    const std::vector<RegionSummary> regions = label_regions(m);
    ASSERT_EQ(regions.size(), c.regions) << c.model;
    double total = 0;
    for (std::size_t r = 1; r < regions.size(); ++r) {
      EXPECT_GT(regions[r].volume, 0) << c.model << " region " << r;
      EXPECT_EQ(regions[r].pieces, 1u);
      total += regions[r].volume;
    }
    EXPECT_NEAR(total, c.total, 1e-9 * c.total) << c.model;
  }
}

TEST(LabelRegions, NestedHeadLayersAreTheDifferencesOfTheirShells) {
  SurfaceMesh m = read_mesh(test::model("openmeeg_HeadNNb3.obj"));
  (void)validate(m);
  const std::vector<RegionSummary> regions = label_regions(m);
  ASSERT_EQ(regions.size(), 6u);
  // Shell volumes (vorocrust info): scalp 4.152740322, skull 3.233689626, cortex 2.734592682,
  // two inclusions 0.1058125506 each.
  EXPECT_NEAR(regions[1].volume, 2.734592682 - 2 * 0.1058125506, 1e-8);
  EXPECT_NEAR(regions[2].volume, 3.233689626 - 2.734592682, 1e-8);
  EXPECT_NEAR(regions[3].volume, 4.152740322 - 3.233689626, 1e-8);
  EXPECT_NEAR(regions[4].volume, 0.1058125506, 1e-9);
  EXPECT_NEAR(regions[5].volume, 0.1058125506, 1e-9);
}

TEST(LabelRegions, GivenLabelsNameTheirRegionsAndTheOutsideTakesLabelZero) {
  Builder b;
  b.box(Point(0, 0, 0), Point(3, 3, 3));
  b.box(Point(1, 1, 1), Point(2, 2, 2));
  b.mesh.region_names = {"core", "air"};
  b.mesh.face_regions.assign(b.mesh.num_faces(), RegionPair{});
  b.mesh.face_regions[0] = RegionPair{RegionPair::kUnknownRegion, 1};  // the outer box's front: air
  b.mesh.face_regions[12] = RegionPair{0, RegionPair::kUnknownRegion};  // the inner box's back: core
  const std::vector<RegionSummary> regions = label_regions(b.mesh);
  // The space between, met first (behind face 0), gets the first free label.
  EXPECT_EQ(b.mesh.region_names, (std::vector<std::string>{"air", "region1", "core"}));
  ASSERT_EQ(regions.size(), 3u);
  EXPECT_EQ(faces_with(b.mesh, {1, 0}), 12u);
  EXPECT_EQ(faces_with(b.mesh, {2, 1}), 12u);
}

TEST(LabelRegions, OneLabelMayNameSeveralPieces) {
  Builder b;
  b.box(Point(0, 0, 0), Point(1, 1, 1));
  b.box(Point(2, 0, 0), Point(3, 1, 1));
  b.mesh.region_names = {"steel"};
  b.mesh.face_regions.assign(b.mesh.num_faces(), RegionPair{0, RegionPair::kUnknownRegion});
  const std::vector<RegionSummary> regions = label_regions(b.mesh);
  EXPECT_EQ(b.mesh.region_names, (std::vector<std::string>{"outside", "steel"}));
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_EQ(regions[1].pieces, 2u);
  EXPECT_NEAR(regions[1].volume, 2.0, 1e-12);
}

TEST(LabelRegions, TwoLabelsOnOneRegionAreAnErrorNamingBothFaces) {
  Builder b;
  b.box(Point(0, 0, 0), Point(1, 1, 1));
  b.mesh.region_names = {"steel", "copper", "air"};
  b.mesh.face_regions.assign(b.mesh.num_faces(), RegionPair{0, 2});
  b.mesh.face_regions[7] = RegionPair{1, 2};
  try {
    label_regions(b.mesh);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::InvalidGeometry);
    EXPECT_EQ(e.message(), "the back of face 0 and the back of face 7 face one region of space, but the first names it "
                           "steel and the second copper");
    EXPECT_EQ(e.where().face, 7u);
  }
}

TEST(LabelRegions, SolidsFromSeparatePartsAreNamedAfterThemAndShareTheirCommonFace) {
  // Two unit cubes side by side, each a part of its own, both with outward normals; the cube
  // at x in [1, 2] is given inside out, which merging turns outward.
  const auto cube_arrays = [](double x0, bool inward) {
    Builder b;
    b.box(Point(x0, 0, 0), Point(x0 + 1, 1, 1));
    if (inward) {
      for (std::size_t f = 0; f < b.mesh.num_faces(); ++f) b.mesh.flip(f);
    }
    std::vector<double> xyz;
    for (const Point& p : b.mesh.vertices) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
    std::vector<std::int64_t> corners;
    for (const Triangle& t : b.mesh.triangles) corners.insert(corners.end(), t.begin(), t.end());
    return std::pair{xyz, corners};
  };
  const auto [xyz_a, corners_a] = cube_arrays(0, false);
  const auto [xyz_b, corners_b] = cube_arrays(1, true);
  const std::vector<NamedSurface> parts{{"steel", surface_from_arrays(xyz_a, corners_a, "steel")},
                                        {"copper", surface_from_arrays(xyz_b, corners_b, "copper")}};
  SurfaceMesh m = merge_surfaces(parts);
  EXPECT_EQ(m.num_faces(), 22u);  // the common square once
  const std::vector<RegionSummary> regions = label_regions(m);
  EXPECT_EQ(m.region_names, (std::vector<std::string>{"outside", "steel", "copper"}));
  ASSERT_EQ(regions.size(), 3u);
  EXPECT_NEAR(regions[1].volume, 1.0, 1e-12);
  EXPECT_NEAR(regions[2].volume, 1.0, 1e-12);
  EXPECT_EQ(faces_with(m, {1, 2}), 2u);
  EXPECT_EQ(faces_with(m, {1, 0}), 10u);
  EXPECT_EQ(faces_with(m, {2, 0}), 10u);
}

TEST(LabelRegions, TwoSolidsFillingTheSameSpaceAreAnError) {
  test::TempDir dir("regions");
  const auto cube = test::data("invalid/cube.off");
  std::filesystem::copy_file(cube, dir / "twin.off");
  try {
    read_meshes({cube, dir / "twin.off"});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::InvalidGeometry);
    EXPECT_NE(e.message().find("solids may touch but not overlap"), std::string::npos) << e.what();
    EXPECT_NE(e.message().find("part twin, which puts twin where the first puts cube"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vorocrust
