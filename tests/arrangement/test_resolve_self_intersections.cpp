// Faces that cut through each other, cut along their intersection curves: what is left meets
// itself only along shared edges, the pieces of space join the input's regions, and the areas
// and volumes are those of the solids the input describes.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "geometry/self_intersections.hpp"
#include "surface_builder.hpp"
#include "test_support.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/read_mesh.hpp"
#include "vorocrust/regions.hpp"
#include "vorocrust/resolve_self_intersections.hpp"
#include "vorocrust/validate.hpp"

namespace vorocrust {
namespace {

Point normal_of(const SurfaceMesh& m, Index f) {
  const Triangle& t = m.triangles[f];
  return (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]);
}

double area_of(const SurfaceMesh& m, Index f) { return 0.5 * normal_of(m, f).norm(); }

// Area of the faces between each pair of regions, smaller label first.
std::map<std::pair<std::int32_t, std::int32_t>, double> interface_areas(const SurfaceMesh& m) {
  std::map<std::pair<std::int32_t, std::int32_t>, double> areas;
  for (Index f = 0; f < m.num_faces(); ++f) {
    const RegionPair& r = m.face_regions[f];
    areas[{std::min(r.back, r.front), std::max(r.back, r.front)}] += area_of(m, f);
  }
  return areas;
}

std::map<std::string, double> volumes_by_name(SurfaceMesh m) {
  std::map<std::string, double> volumes;
  for (const RegionSummary& r : label_regions(m)) volumes[r.name] = r.volume;
  return volumes;
}

TEST(ResolveSelfIntersections, LeavesASurfaceThatDoesNotCutItselfAsItIs) {
  test::SurfaceBuilder b;
  b.box(Point(0, 0, 0), Point(1, 1, 1));
  SelfIntersectionStats stats;
  const SurfaceMesh resolved = resolve_self_intersections(b.mesh, &stats);
  EXPECT_EQ(stats.face_pairs, 0u);
  EXPECT_EQ(stats.faces_cut, 0u);
  EXPECT_EQ(resolved.triangles, b.mesh.triangles);
  EXPECT_EQ(resolved.vertices, b.mesh.vertices);
}

// Two overlapping boxes: the overlap joins the box whose faces bound it over the larger area (the
// smaller box's five sides inside the larger one, against the larger one's one side inside the
// smaller); those five sides become the interface, and the larger box's side inside the smaller
// one, now inside one solid, is dropped.
TEST(ResolveSelfIntersections, OverlappingSolidsTouchAlongTheOverlap) {
  test::SurfaceBuilder b;
  b.box(Point(0, 0, 0), Point(1, 1, 1));
  b.box(Point(0.5, 0.2, 0.3), Point(1.5, 0.7, 0.8));
  SelfIntersectionStats stats;
  const SurfaceMesh resolved = resolve_self_intersections(b.mesh, &stats);
  EXPECT_GT(stats.face_pairs, 0u);
  EXPECT_GT(stats.faces_dropped, 0u);
  EXPECT_EQ(stats.faces, resolved.num_faces());
  EXPECT_TRUE(geometry::find_self_intersections(resolved).empty());

  const auto volumes = volumes_by_name(resolved);
  ASSERT_EQ(volumes.size(), 3u);
  EXPECT_NEAR(volumes.at("region1"), 1 - 0.5 * 0.5 * 0.5, 1e-12);
  EXPECT_NEAR(volumes.at("region2"), 1 * 0.5 * 0.5, 1e-12);
  const auto areas = interface_areas(resolved);
  EXPECT_NEAR(areas.at({1, 2}), 5 * 0.5 * 0.5, 1e-12);
  EXPECT_NEAR(areas.at({0, 1}), 6 - 0.5 * 0.5, 1e-12);
  EXPECT_NEAR(areas.at({0, 2}), 5 * 0.5 * 0.5, 1e-12);
  EXPECT_EQ(areas.size(), 3u);
}

// An inner solid poking out through the outer one's side, as a coarse brain layer through the
// skull: the part outside claims only the inner solid's boundary, so the inner solid keeps its
// whole volume, and the outer one loses what the inner one takes.
TEST(ResolveSelfIntersections, AnInnerSolidPokingThroughKeepsItsVolume) {
  test::SurfaceBuilder b;
  b.box(Point(0, 0, 0), Point(1, 1, 1));
  b.box(Point(0.3, 0.35, 0.8), Point(0.6, 0.65, 1.2));
  const SurfaceMesh resolved = resolve_self_intersections(b.mesh);
  EXPECT_TRUE(geometry::find_self_intersections(resolved).empty());
  const auto volumes = volumes_by_name(resolved);
  ASSERT_EQ(volumes.size(), 3u);
  EXPECT_NEAR(volumes.at("region1"), 1 - 0.3 * 0.3 * 0.2, 1e-12);
  EXPECT_NEAR(volumes.at("region2"), 0.3 * 0.3 * 0.4, 1e-12);
}

// Boxes turned so that no edge or vertex of one lies on the other: the cut faces are pieces of
// their input faces, in the same plane and turned the same way.
TEST(ResolveSelfIntersections, PiecesKeepTheirFacesPlaneOrientationAndArea) {
  test::SurfaceBuilder b;
  b.box(Point(0, 0, 0), Point(1, 1, 1));
  const Eigen::Isometry3d turned = Eigen::Translation3d(0.55, 0.45, 0.5) *
                                   Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized());
  b.box(Point(-0.3, -0.3, -0.3), Point(0.3, 0.3, 0.3), false, turned);
  b.box(Point(0, -0.2, -0.2), Point(1.0, 0.2, 0.2), false, Eigen::Translation3d(0.6, 0.5, 0.5) *
                                                              Eigen::AngleAxisd(0.3, Eigen::Vector3d(0, 1, 1).normalized()));
  SurfaceMesh input = b.mesh;
  input.face_line.clear();
  for (Index f = 0; f < input.num_faces(); ++f) input.face_line.push_back(f + 1);  // parent of each piece
  const SurfaceMesh arranged = resolve_self_intersections(input);
  EXPECT_TRUE(geometry::find_self_intersections(arranged).empty());
  // Every kept piece lies in its input face's plane with the same orientation.
  for (Index f = 0; f < arranged.num_faces(); ++f) {
    const Index parent = arranged.face_line[f] - 1;
    const Point n = normal_of(input, parent).normalized();
    const Triangle& t = arranged.triangles[f];
    for (Index v : t) EXPECT_NEAR(n.dot(arranged.vertices[v] - input.vertices[input.triangles[parent][0]]), 0, 1e-12);
    EXPECT_GT(normal_of(arranged, f).dot(n), 0) << "piece " << f << " of face " << parent;
  }
  // Each solid keeps a piece of space of its own.
  EXPECT_EQ(volumes_by_name(arranged).size(), 4u);
}

// Three sheets in the three coordinate planes cross pairwise along the axes, and all three at the
// origin: the origin becomes one vertex of all three sheets' pieces, and every sheet keeps its area.
TEST(ResolveSelfIntersections, CurvesCrossingInsideAFaceShareOnePoint) {
  SurfaceMesh m;
  m.groups.push_back({"sheets", ""});
  m.vertices = {Point(-1, -0.8, 0), Point(1.1, -0.7, 0), Point(0.1, 1.2, 0),   // z = 0
                Point(-0.9, 0, -1), Point(1.2, 0, -0.6), Point(0.2, 0, 1.3),   // y = 0
                Point(0, -1.1, -0.9), Point(0, 1.3, -0.8), Point(0, 0.1, 1.4)};  // x = 0
  m.add_triangle({0, 1, 2}, 0);
  m.add_triangle({3, 4, 5}, 0);
  m.add_triangle({6, 7, 8}, 0);
  const double areas[3] = {area_of(m, 0), area_of(m, 1), area_of(m, 2)};
  SelfIntersectionStats stats;
  SurfaceMesh input = m;
  input.face_line = {1, 2, 3};
  const SurfaceMesh arranged = resolve_self_intersections(input, &stats);
  EXPECT_EQ(stats.face_pairs, 3u);
  EXPECT_EQ(stats.faces_cut, 3u);
  EXPECT_EQ(stats.faces_dropped, 0u);  // sheets have the outside on both sides
  EXPECT_TRUE(geometry::find_self_intersections(arranged).empty());
  double piece_areas[3] = {0, 0, 0};
  for (Index f = 0; f < arranged.num_faces(); ++f) piece_areas[arranged.face_line[f] - 1] += area_of(arranged, f);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(piece_areas[k], areas[k], 1e-12);
  int at_origin = -1;
  for (Index v = 0; v < arranged.num_vertices(); ++v) {
    if (arranged.vertices[v].norm() < 1e-14) at_origin = static_cast<int>(v);
  }
  ASSERT_GE(at_origin, 0);
  bool holds[3] = {false, false, false};
  for (Index f = 0; f < arranged.num_faces(); ++f) {
    for (Index v : arranged.triangles[f]) holds[arranged.face_line[f] - 1] |= static_cast<int>(v) == at_origin;
  }
  EXPECT_TRUE(holds[0] && holds[1] && holds[2]);
}

TEST(ResolveSelfIntersections, FacesOverlappingInOnePlaneAreRefusedNamingBoth) {
  SurfaceMesh m;
  m.groups.push_back({"flat", "flat.obj"});
  m.vertices = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0.2, 0.2, 0), Point(1.2, 0.2, 0), Point(0.2, 1.2, 0)};
  m.add_triangle({0, 1, 2}, 0, 7);
  m.add_triangle({3, 4, 5}, 0, 8);
  try {
    resolve_self_intersections(m);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::InvalidGeometry);
    EXPECT_NE(std::string(e.what()).find("flat.obj line 7"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("flat.obj line 8"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("common plane"), std::string::npos) << e.what();
  }
}

// The shared models that cut through themselves: a fold of one scan (bimba), a brain layer through
// the skull (HeadNNa1), bones overlapping their neighbours, an open scan folding over itself.
TEST(ResolveSelfIntersections, SharedModelsNoLongerCutThemselves) {
  struct Case {
    const char* name;
    std::size_t regions;  // outside included
  };
  for (const Case& c : {Case{"directional_bimba.off", 2}, Case{"openmeeg_HeadNNa1.obj", 5},
                        Case{"cgal_bones.off", 27}, Case{"igl_camelhead.off", 1}}) {
    SCOPED_TRACE(c.name);
    SurfaceMesh input = read_mesh(test::model(c.name));
    // Unfolding would take igl_camelhead's crossings away with its folds.
    validate(input, {.fix_folds = false, .self_intersections_are_errors = false});
    ASSERT_FALSE(geometry::find_self_intersections(input).empty());
    const SurfaceMesh before = input;
    SelfIntersectionStats stats;
    SurfaceMesh resolved = resolve_self_intersections(input, &stats);
    EXPECT_TRUE(geometry::find_self_intersections(resolved).empty());
    EXPECT_GT(stats.faces_cut, 0u);
    const std::vector<RegionSummary> regions = label_regions(resolved);
    EXPECT_EQ(regions.size(), c.regions);
    // Pieces name the input file and line of the face they came from.
    EXPECT_NE(describe_face(resolved, 0).find(c.name), std::string::npos);
    // Cutting moves no surface: the total area changes only by the faces left inside a region.
    double area_before = 0, area_after = 0;
    for (Index f = 0; f < before.num_faces(); ++f) area_before += area_of(before, f);
    for (Index f = 0; f < resolved.num_faces(); ++f) area_after += area_of(resolved, f);
    if (stats.faces_dropped == 0) {
      EXPECT_NEAR(area_after, area_before, 1e-9 * area_before);
    }
    EXPECT_LE(area_after, area_before * (1 + 1e-12));
  }
}

}  // namespace
}  // namespace vorocrust
