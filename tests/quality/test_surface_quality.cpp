// The surface-quality figures (paper section 3) on shapes whose answers are known.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/triangle_shape.hpp"
#include "surface_builder.hpp"
#include "test_support.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/quality.hpp"
#include "vorocrust/read_mesh.hpp"
#include "vorocrust/threads.hpp"

namespace vorocrust {
namespace {

SurfaceMesh triangles(std::vector<Point> vertices, const std::vector<Triangle>& faces) {
  SurfaceMesh m;
  m.groups.push_back({"test", ""});
  m.vertices = std::move(vertices);
  for (const Triangle& t : faces) m.add_triangle(t, 0);
  return m;
}

SurfaceMesh one_triangle(const Point& a, const Point& b, const Point& c) { return triangles({a, b, c}, {{0, 1, 2}}); }

// The unit square [0, w] x [0, 1] in the plane z, cut into n x n pairs of triangles.
SurfaceMesh grid(int n, double z, double w = 1) {
  SurfaceMesh m;
  m.groups.push_back({"grid", ""});
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.vertices.emplace_back(w * i / n, static_cast<double>(j) / n, z);
  const auto at = [&](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      m.add_triangle({at(i, j), at(i + 1, j), at(i + 1, j + 1)}, 0);
      m.add_triangle({at(i, j), at(i + 1, j + 1), at(i, j + 1)}, 0);
    }
  }
  return m;
}

SurfaceMesh translated(SurfaceMesh m, const Point& by) {
  for (Point& p : m.vertices) p += by;
  return m;
}

SurfaceQuality of_itself(const SurfaceMesh& m) { return measure_surface_quality(m, m); }

TEST(SurfaceQuality, EquilateralTriangleHasQualityOneAndAnglesOfSixty) {
  const SurfaceQuality q = of_itself(one_triangle(Point(0, 0, 0), Point(1, 0, 0), Point(0.5, std::sqrt(3.0) / 2, 0)));
  EXPECT_EQ(q.triangles, 1u);
  EXPECT_NEAR(q.min_quality, 1.0, 1e-12);
  EXPECT_NEAR(q.mean_quality, 1.0, 1e-12);
  EXPECT_NEAR(q.min_angle_degrees, 60.0, 1e-12);
  EXPECT_NEAR(q.max_angle_degrees, 60.0, 1e-12);
  EXPECT_EQ(q.percent_angles_below_30, 0.0);
  EXPECT_EQ(q.percent_angles_above_90, 0.0);
  ASSERT_EQ(q.quality_histogram.size(), QualityOptions{}.histogram_bins);
  EXPECT_EQ(q.quality_histogram.back(), 1u);  // Q = 1 belongs to the last bin
}

TEST(SurfaceQuality, RightAngleIsNotAboveNinety) {
  const SurfaceQuality q = of_itself(one_triangle(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)));
  EXPECT_NEAR(q.max_angle_degrees, 90.0, 1e-12);
  EXPECT_NEAR(q.min_angle_degrees, 45.0, 1e-12);
  EXPECT_EQ(q.percent_angles_above_90, 0.0);  // strict: 90 is not above 90
  EXPECT_EQ(q.percent_angles_below_30, 0.0);
  // 6 S / (sqrt(3) h p) with S = 1/2, h = sqrt(2), p = (2 + sqrt(2)) / 2, which is also
  // 2 sqrt(3) r / h with the inradius r = (2 - sqrt(2)) / 2.
  const double expected = 3.0 / (std::sqrt(3.0) * std::sqrt(2.0) * (2 + std::sqrt(2.0)) / 2);
  EXPECT_NEAR(q.min_quality, expected, 1e-12);
  EXPECT_NEAR(q.min_quality, 2 * std::sqrt(3.0) * (2 - std::sqrt(2.0)) / 2 / std::sqrt(2.0), 1e-12);
}

TEST(SurfaceQuality, ObtuseAndNeedleAnglesAreCounted) {
  // Corner 0 opens just past 90 degrees; the needle has two angles far below 30.
  const SurfaceMesh m = triangles({Point(0, 0, 0), Point(1, 0, 0), Point(-0.001, 1, 0), Point(0, 5, 0),
                                   Point(10, 5, 0), Point(5, 5.1, 0)},
                                  {{0, 1, 2}, {3, 4, 5}});
  const SurfaceQuality q = of_itself(m);
  EXPECT_NEAR(q.percent_angles_above_90, 100.0 * 2 / 6, 1e-12);  // the obtuse corner and the needle's tip
  EXPECT_NEAR(q.percent_angles_below_30, 100.0 * 2 / 6, 1e-12);
  EXPECT_GT(q.max_angle_degrees, 90.0);
  EXPECT_NEAR(q.min_angle_degrees, std::atan2(0.1, 5.0) * 180 / std::numbers::pi, 1e-9);
  EXPECT_LT(q.min_quality, 0.1);
}

TEST(SurfaceQuality, DegenerateTrianglesGiveZeroQualityAndNoNaN) {
  // A proper triangle, a flat one (three points on a line) and one with a repeated corner.
  const SurfaceMesh m = triangles({Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(2, 0, 0), Point(3, 0, 0)},
                                  {{0, 1, 2}, {1, 3, 4}, {0, 0, 2}});
  const SurfaceQuality q = of_itself(m);
  for (double x : {q.min_angle_degrees, q.max_angle_degrees, q.percent_angles_below_30, q.percent_angles_above_90,
                   q.min_quality, q.mean_quality, q.hausdorff, q.hausdorff_relative}) {
    EXPECT_TRUE(std::isfinite(x));
  }
  EXPECT_EQ(q.min_quality, 0.0);
  EXPECT_EQ(q.quality_histogram.front(), 2u);
  EXPECT_EQ(q.min_angle_degrees, 0.0);
  EXPECT_NEAR(q.max_angle_degrees, 180.0, 1e-12);  // the flat triangle's middle corner
  EXPECT_EQ(q.hausdorff, 0.0);
  const geometry::TriangleShape point = geometry::triangle_shape(Point(1, 1, 1), Point(1, 1, 1), Point(1, 1, 1));
  EXPECT_EQ(point.quality, 0.0);
  for (double a : point.angles_degrees) EXPECT_EQ(a, 0.0);
}

TEST(SurfaceQuality, PerFaceQualitiesAreInFaceOrderAndSummariseToTheFigures) {
  // Equilateral, right isosceles, flat: Q = 1, 2 sqrt(3) r / h with r = (2 - sqrt(2)) / 2, 0.
  const SurfaceMesh m = triangles({Point(0, 0, 0), Point(1, 0, 0), Point(0.5, std::sqrt(3.0) / 2, 0),
                                   Point(0, 1, 0), Point(2, 0, 0)},
                                  {{0, 1, 2}, {0, 1, 3}, {0, 1, 4}});
  const std::vector<double> q = triangle_qualities(m);
  ASSERT_EQ(q.size(), 3u);
  EXPECT_NEAR(q[0], 1.0, 1e-12);
  EXPECT_NEAR(q[1], std::sqrt(3.0) * (2 - std::sqrt(2.0)) / std::sqrt(2.0), 1e-12);
  EXPECT_EQ(q[2], 0.0);
  const SurfaceQuality figures = of_itself(m);
  EXPECT_EQ(figures.min_quality, q[2]);
  EXPECT_NEAR(figures.mean_quality, (q[0] + q[1] + q[2]) / 3, 1e-15);
  EXPECT_TRUE(triangle_qualities(SurfaceMesh{}).empty());
}

TEST(SurfaceQuality, AMeshAgainstItselfIsAtDistanceZeroWithTheSameTopology) {
  const SurfaceMesh bunny = read_mesh(test::model("igl_bunny.off"));
  const SurfaceQuality q = of_itself(bunny);
  EXPECT_EQ(q.hausdorff, 0.0);  // rounding is not distance
  EXPECT_TRUE(q.topology_matches);
  EXPECT_EQ(q.triangles, 6966u);
  // Vertices, edge midpoints and the random points.
  EXPECT_EQ(q.input_samples, 3485u + 10449u + QualityOptions{}.random_samples);
  std::size_t binned = 0;
  for (std::size_t n : q.quality_histogram) binned += n;
  EXPECT_EQ(binned, q.triangles);
  EXPECT_GT(q.min_quality, 0.0);
  EXPECT_LE(q.min_quality, q.mean_quality);
  EXPECT_LE(q.mean_quality, 1.0);
}

TEST(SurfaceQuality, ACopyMovedAlongItsNormalIsThatFarAway) {
  const SurfaceMesh flat = grid(20, 0.0);
  const double d = 0.037;
  const SurfaceQuality q = measure_surface_quality(flat, translated(flat, Point(0, 0, d)));
  EXPECT_NEAR(q.hausdorff, d, 1e-12);
  EXPECT_NEAR(q.input_to_output, d, 1e-12);
  EXPECT_NEAR(q.output_to_input, d, 1e-12);
  EXPECT_NEAR(q.hausdorff_relative, d / std::sqrt(2.0), 1e-12);
  EXPECT_TRUE(q.topology_matches);  // one open disc each
}

TEST(SurfaceQuality, OneSidedDistancesAreTheRightWayRound) {
  // The output reaches one unit past the input's far edge; the input lies wholly on the output.
  const SurfaceQuality q = measure_surface_quality(grid(4, 0.0, 1.0), grid(8, 0.0, 2.0));
  EXPECT_EQ(q.input_to_output, 0.0);
  EXPECT_NEAR(q.output_to_input, 1.0, 1e-12);
  EXPECT_NEAR(q.hausdorff, 1.0, 1e-12);
}

TEST(SurfaceQuality, AShiftedClosedSurfaceIsAtMostTheShiftAway) {
  const SurfaceMesh bunny = read_mesh(test::model("igl_bunny.off"));
  const SurfaceQuality itself = of_itself(bunny);
  const Point shift = 1e-3 * itself.bounding_box_diagonal * Point(1, 2, 2) / 3;
  const SurfaceQuality q = measure_surface_quality(bunny, translated(bunny, shift));
  EXPECT_LE(q.hausdorff, shift.norm() * (1 + 1e-9));
  // Where the surface faces the shift, its samples are nearly the whole shift away.
  EXPECT_GT(q.hausdorff, 0.9 * shift.norm());
}

TEST(SurfaceQuality, FiguresDoNotDependOnTheThreadCount) {
  const SurfaceMesh bunny = read_mesh(test::model("igl_bunny.off"));
  const SurfaceMesh moved = translated(bunny, Point(1e-4, -2e-4, 3e-4));
  SurfaceQuality one, all;
  {
    const ThreadLimit limit(1);
    one = measure_surface_quality(bunny, moved);
  }
  all = measure_surface_quality(bunny, moved);
  EXPECT_EQ(one.hausdorff, all.hausdorff);
  EXPECT_EQ(one.input_to_output, all.input_to_output);
  EXPECT_EQ(one.output_to_input, all.output_to_input);
  EXPECT_EQ(one.mean_quality, all.mean_quality);
  EXPECT_EQ(one.quality_histogram, all.quality_histogram);
}

SurfaceMesh box_mesh(const Point& lo, const Point& hi) {
  test::SurfaceBuilder b;
  b.box(lo, hi);
  return b.mesh;
}

TEST(SurfaceQuality, EnclosedVolumesAreTheRegionsButTheOutside) {
  // A unit cube against a cube of side 0.9: 27.1 % of the volume lost.
  const SurfaceQuality shrunk =
      measure_surface_quality(box_mesh(Point::Zero(), Point::Ones()), box_mesh(Point::Zero(), Point::Constant(0.9)));
  ASSERT_TRUE(shrunk.input_volume && shrunk.output_volume);
  EXPECT_NEAR(*shrunk.input_volume, 1.0, 1e-12);
  EXPECT_NEAR(*shrunk.output_volume, 0.729, 1e-12);
  ASSERT_TRUE(shrunk.volume_change_percent());
  EXPECT_NEAR(*shrunk.volume_change_percent(), -27.1, 1e-9);
  ASSERT_EQ(shrunk.region_volumes.size(), 1u);
  EXPECT_EQ(shrunk.region_volumes[0].name, "inside");

  // Unlabelled nested shells cut out two regions, the shell between them (63) and the core (1).
  test::SurfaceBuilder nested;
  nested.box(Point::Zero(), Point::Constant(4));
  nested.box(Point::Ones(), Point::Constant(2));
  const SurfaceQuality two = of_itself(nested.mesh);
  EXPECT_EQ(two.input_volume, std::optional(64.0));
  ASSERT_EQ(two.region_volumes.size(), 2u);
  EXPECT_NEAR(*two.region_volumes[0].input + *two.region_volumes[1].input, 64.0, 1e-9);
  // Labelled as a hollow shell, the core is a cavity of the outside: 63 alone.
  SurfaceMesh hollow = nested.mesh;
  hollow.region_names = {"outside", "shell"};
  hollow.face_regions.assign(hollow.num_faces(), RegionPair{1, 0});  // outer sides, normals out
  for (std::size_t f = 12; f < 24; ++f) hollow.face_regions[f] = RegionPair{0, 1};  // the core's sides face the shell
  const SurfaceQuality shell = of_itself(hollow);
  ASSERT_TRUE(shell.input_volume);
  EXPECT_NEAR(*shell.input_volume, 63.0, 1e-9);
  ASSERT_EQ(shell.region_volumes.size(), 1u);
  EXPECT_EQ(shell.region_volumes[0].name, "shell");
  EXPECT_EQ(shell.region_volumes[0].change_percent(), std::optional(0.0));

  // Labels at odds on one region of space: no volume to tell, and no error.
  SurfaceMesh odd = box_mesh(Point::Zero(), Point::Ones());
  odd.region_names = {"outside", "a", "b"};
  odd.face_regions.assign(odd.num_faces(), RegionPair{1, 0});
  odd.face_regions[0] = RegionPair{2, 0};
  const SurfaceQuality unknown = measure_surface_quality(box_mesh(Point::Zero(), Point::Ones()), odd);
  EXPECT_TRUE(unknown.input_volume);
  EXPECT_FALSE(unknown.output_volume);
  EXPECT_FALSE(unknown.volume_change_percent());

  // An open sheet encloses nothing.
  const SurfaceQuality sheet = of_itself(grid(4, 0.0));
  EXPECT_EQ(sheet.input_volume, std::optional(0.0));
  EXPECT_EQ(sheet.output_volume, std::optional(0.0));
  EXPECT_FALSE(sheet.volume_change_percent());
}

TEST(SurfaceTopology, SphereAndTorusDiffer) {
  const SurfaceMesh bunny = read_mesh(test::model("igl_bunny.off"));
  const SurfaceMesh torus = read_mesh(test::model("sandia_torus.obj"));
  const SurfaceTopology b = surface_topology(bunny), t = surface_topology(torus);
  EXPECT_EQ(b.euler_characteristic, std::vector<long>{2});
  EXPECT_EQ(t.euler_characteristic, std::vector<long>{0});
  EXPECT_EQ(b.closed, std::vector<bool>{true});
  EXPECT_EQ(t.closed, std::vector<bool>{true});
  EXPECT_FALSE(same_topology(b, t));
  EXPECT_TRUE(same_topology(t, t));
  const SurfaceQuality q = measure_surface_quality(bunny, torus);
  EXPECT_FALSE(q.topology_matches);
  EXPECT_EQ(q.input_topology.euler_characteristic, std::vector<long>{2});
  EXPECT_EQ(q.output_topology.euler_characteristic, std::vector<long>{0});
}

TEST(SurfaceTopology, ComponentsAreCountedOnMultiComponentModels) {
  const SurfaceTopology bones = surface_topology(read_mesh(test::model("cgal_bones.off")));
  EXPECT_EQ(bones.components, 26u);
  EXPECT_EQ(bones.euler_characteristic, std::vector<long>(26, 2));
  const SurfaceTopology knot = surface_topology(read_mesh(test::model("cgal_knot2.off")));
  EXPECT_EQ(knot.components, 2u);  // two linked tori
  EXPECT_EQ(knot.euler_characteristic, (std::vector<long>{0, 0}));
  const SurfaceTopology head = surface_topology(read_mesh(test::model("openmeeg_HeadNNb3.obj")));
  EXPECT_EQ(head.components, 5u);
  EXPECT_FALSE(same_topology(bones, head));
}

TEST(SurfaceTopology, OpenAndNonManifoldSurfaces) {
  const SurfaceTopology terrain = surface_topology(read_mesh(test::model("gmsh_terrain.stl")));
  EXPECT_EQ(terrain.components, 1u);
  EXPECT_EQ(terrain.closed, std::vector<bool>{false});
  EXPECT_EQ(terrain.euler_characteristic, std::vector<long>{1});  // a disc
  EXPECT_EQ(terrain.boundary_edges, 126u);
  const SurfaceTopology cubes = surface_topology(read_mesh(test::model("cgal_cubes_edge_contact.off")));
  EXPECT_EQ(cubes.components, 1u);
  EXPECT_EQ(cubes.non_manifold_edges, 1u);
  // An open disc and a closed sphere have different Euler characteristics, but so do the
  // closedness flags: a closed disc-like surface is no match for an open disc.
  SurfaceTopology closed_disc = terrain;
  closed_disc.closed = {true};
  EXPECT_FALSE(same_topology(terrain, closed_disc));
}

TEST(SurfaceQuality, RefusesEmptySurfacesAndBadOptions) {
  const SurfaceMesh square = grid(1, 0.0);
  EXPECT_THROW(measure_surface_quality(square, SurfaceMesh{}), Error);
  EXPECT_THROW(measure_surface_quality(SurfaceMesh{}, square), Error);
  QualityOptions bad;
  bad.histogram_bins = 0;
  try {
    measure_surface_quality(square, square, bad);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Usage);
    EXPECT_NE(std::string(e.what()).find("bins"), std::string::npos);
  }
  const SurfaceMesh point = one_triangle(Point(1, 1, 1), Point(1, 1, 1), Point(1, 1, 1));
  try {
    measure_surface_quality(point, square);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::InvalidGeometry);
  }
}

}  // namespace
}  // namespace vorocrust
