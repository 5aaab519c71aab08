// The 2D mesher (paper 2.6) on the domains: convex cells, edges orthogonal to the seed
// links, every input segment followed by cell edges, region areas equal to the input's.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <numeric>

#include "test_support.hpp"
#include "vorocrust/plane.hpp"

namespace vorocrust {
namespace {

double distance_to_segment(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

// How far p lies from the input's segments.
double distance_to_input(const PlanarDomain& d, const Point2& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& s : d.segments) best = std::min(best, distance_to_segment(p, d.points[s[0]], d.points[s[1]]));
  return best;
}

double input_length(const PlanarDomain& d) {
  double total = 0;
  for (const auto& s : d.segments) total += (d.points[s[1]] - d.points[s[0]]).norm();
  return total;
}

struct Figures {
  double on_input_length = 0;    // edges lying on the input, each once
  double farthest_vertex = 0;    // of the edges between regions, from the input
  double farthest_midpoint = 0;  // of the same edges
  std::size_t region_edges = 0;
};

Figures edges_on_input(const PlanarDomain& d, const PlaneMesh& m, double tolerance) {
  Figures f;
  for (std::size_t c = 0; c < m.cells.size(); ++c) {
    const PlaneCell& cell = m.cells[c];
    const std::size_t n = cell.points.size();
    for (std::size_t k = 0; k < n; ++k) {
      const std::int32_t other = cell.across[k];
      if (other != kNoCell && static_cast<std::size_t>(other) < c) continue;  // counted from the lower cell
      const Point2 &a = m.points[cell.points[k]], &b = m.points[cell.points[(k + 1) % n]];
      const double da = distance_to_input(d, a), db = distance_to_input(d, b), dm = distance_to_input(d, (a + b) / 2);
      if (da <= tolerance && db <= tolerance && dm <= tolerance) f.on_input_length += (b - a).norm();
      if (cell.regions_across[k] != cell.region) {
        ++f.region_edges;
        f.farthest_vertex = std::max({f.farthest_vertex, da, db});
        f.farthest_midpoint = std::max(f.farthest_midpoint, dm);
      }
    }
  }
  return f;
}

// What every 2D mesh must satisfy.
void expect_conforming(const PlaneMesh& mesh, const PlaneQuality& q) {
  EXPECT_TRUE(q.convex);
  EXPECT_LT(q.max_link_angle, 1e-6) << "an edge is not orthogonal to its seeds' link";
  EXPECT_GT(q.cells, 50u);
  double total = 0;
  for (const PlaneCell& c : mesh.cells) {
    EXPECT_GT(c.area, 0);
    total += c.area;
  }
  EXPECT_NEAR(total, std::accumulate(q.area_by_region.begin(), q.area_by_region.end(), 0.0), 1e-12 * total);
}

// A sample domain meshed at `max_size`, checked for what every mesh must satisfy.
struct Meshed {
  PlanarDomain domain, prepared;
  PlaneMesh mesh;
  PlaneQuality q;
};
Meshed mesh_sample(const std::string& name, double max_size) {
  Meshed m;
  m.domain = read_planar_domain(test::sample_2d(name));
  m.prepared = prepare_planar_domain(m.domain);
  PlaneOptions options;
  options.max_size = max_size;
  m.mesh = mesh_plane(m.domain, options);
  EXPECT_EQ(m.mesh.domain.points, m.prepared.points) << "the mesh keeps the domain it meshed";
  EXPECT_EQ(m.mesh.domain.segments, m.prepared.segments);
  m.q = measure_plane_quality(m.mesh);
  expect_conforming(m.mesh, m.q);
  return m;
}

// A domain of straight segments: cell edges follow every one of them exactly, and every edge
// between two regions lies on one.
void expect_segments_followed_exactly(const Meshed& m) {
  const Figures f = edges_on_input(m.prepared, m.mesh, 1e-9);
  EXPECT_NEAR(f.on_input_length, input_length(m.prepared), 1e-9 * input_length(m.prepared));
  EXPECT_LT(f.farthest_midpoint, 1e-9);
}

TEST(MeshPlane, CrossSectionWithAFaultEndingInsideTheTopLayer) {
  const Meshed m = mesh_sample("cross_section.poly", 0.25);
  const PlaneQuality& q = m.q;
  // Layers under 2 + 0.08 x, between that and 4 - 0.05 x, and above, across 10 x 6.
  ASSERT_EQ(q.area_by_region.size(), 4u);
  EXPECT_NEAR(q.area_by_region[1], 24.0, 1e-9);
  EXPECT_NEAR(q.area_by_region[2], 13.5, 1e-9);
  EXPECT_NEAR(q.area_by_region[3], 22.5, 1e-9);
  // Every segment, the fault too (split where it crosses the layers' bases), is a chain of
  // cell edges, and every edge between regions lies on a segment.
  EXPECT_EQ(m.prepared.segments.size(), m.domain.segments.size() + 4) << "the fault and the two bases it crosses, split there";
  expect_segments_followed_exactly(m);
  // The fault's free end: inside the top layer, its two sides are one region.
  EXPECT_EQ(m.mesh.region_names[3], "region3");
}

TEST(MeshPlane, SquareWithACircularHoleWithinTheChordsSagitta) {
  const Meshed m = mesh_sample("square_hole.poly", 0.05);
  const PlaneQuality& q = m.q;
  const PlaneMesh& mesh = m.mesh;
  const PlanarDomain& domain = m.domain;
  ASSERT_EQ(q.area_by_region.size(), 2u);
  EXPECT_EQ(mesh.region_names[1], "inside");
  // The hole's 48-gon is followed by chords between circle centres on it; a chord of length at
  // most 2 max_size on a circle of radius 0.2 stays within its sagitta.
  const double polygon = 1 - 0.5 * 48 * 0.04 * std::sin(2 * std::numbers::pi / 48);
  const double sagitta = 0.2 - std::sqrt(0.04 - 0.05 * 0.05);
  EXPECT_GE(q.area_by_region[1], polygon - 1e-12);
  EXPECT_LE(q.area_by_region[1], polygon + sagitta * 2 * std::numbers::pi * 0.2);
  const Figures f = edges_on_input(domain, mesh, 1e-9);
  EXPECT_LT(f.farthest_vertex, 1e-9) << "every vertex of the boundary is a circle's centre, on a segment";
  EXPECT_LT(f.farthest_midpoint, sagitta);
  // The square's sides exactly, and of the hole the chords between centres on one segment.
  EXPECT_GE(f.on_input_length, 4.0 - 1e-9);
  EXPECT_LE(f.on_input_length, input_length(domain));
}

TEST(MeshPlane, CornersDownToTenDegrees) {
  const Meshed m = mesh_sample("sharp_corners.poly", 0.1);
  const PlaneQuality& q = m.q;
  expect_segments_followed_exactly(m);
  // The 10-degree wedge: a triangle 2 long, 2 tan(10) high at its end.
  EXPECT_NEAR(q.area_by_region[1], 2 * std::tan(10 * std::numbers::pi / 180), 1e-9);
  EXPECT_GT(q.min_angle, 0);
}

TEST(MeshPlane, ThinChannel) {
  const Meshed m = mesh_sample("thin_channel.poly", 0.1);
  EXPECT_NEAR(m.q.area_by_region[1], 2 + 0.5 * 0.02, 1e-9);
  expect_segments_followed_exactly(m);
  // Cells fill the channel: some cell's centroid lies in it.
  EXPECT_TRUE(std::any_of(m.mesh.cells.begin(), m.mesh.cells.end(), [](const PlaneCell& c) {
    return c.centroid.x() > 1.05 && c.centroid.x() < 1.45 && c.centroid.y() > 0.49 && c.centroid.y() < 0.51;
  }));
}

TEST(MeshPlane, EveryInteriorModeKeepsTheBoundaryAndTheArea) {
  const PlanarDomain domain = read_planar_domain(test::sample_2d("square_hole.poly"));
  std::vector<double> areas;
  for (const InteriorMode mode : {InteriorMode::Random, InteriorMode::Lattice, InteriorMode::Cvt}) {
    PlaneOptions options;
    options.max_size = 0.05;
    options.interior = mode;
    options.cvt_iterations = 10;
    const PlaneMesh mesh = mesh_plane(domain, options);
    const PlaneQuality q = measure_plane_quality(mesh);
    expect_conforming(mesh, q);
    areas.push_back(q.area_by_region[1]);
    // Seeds of the boundary lie on their circles, the interior's outside all of them.
    for (const Seed& s : mesh.seeds) {
      if (s.kind != SeedKind::Interior && s.kind != SeedKind::Outside) continue;
      for (const PlaneCircle& c : mesh.circles) ASSERT_GE((Point2(s.position.x(), s.position.y()) - c.centre).norm(), c.radius);
    }
  }
  // The same boundary; the sums differ only by rounding, over other cells.
  EXPECT_NEAR(areas[0], areas[1], 1e-12);
  EXPECT_NEAR(areas[0], areas[2], 1e-12);
}

TEST(MeshPlane, ALatticeKeepsTheSpacingOfTheCoarsestCircleNotOfTheFinest) {
  // A square with four tiny 64-gons inside: their many small circles must not set the
  // lattice's spacing over the whole square (the median circle once did: a dense lattice).
  PlanarDomain d;
  d.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  for (const Point2& centre : {Point2(0.3, 0.3), Point2(0.7, 0.3), Point2(0.3, 0.7), Point2(0.7, 0.7)}) {
    const auto first = static_cast<Index>(d.points.size());
    for (Index k = 0; k < 64; ++k) {
      const double t = 2 * std::numbers::pi * k / 64;
      d.points.push_back(centre + 0.01 * Point2(std::cos(t), std::sin(t)));
      d.segments.push_back({first + k, first + (k + 1) % 64});
    }
  }
  PlaneOptions random, lattice;
  random.max_size = lattice.max_size = 0.3;
  lattice.interior = InteriorMode::Lattice;
  const PlaneMesh a = mesh_plane(d, random), b = mesh_plane(d, lattice);
  expect_conforming(b, measure_plane_quality(b));
  EXPECT_LT(b.cells.size(), 2 * a.cells.size());
}

TEST(MeshPlane, ASizingFileRefinesWhereItAsks) {
  test::TempDir dir("plane-sizing");
  {
    std::ofstream f(dir / "sizing.txt");
    f << "# x y size\n0 0 0.02\n1 1 0.2\n";
  }
  const PlanarDomain domain = read_planar_domain(test::sample_2d("square_hole.poly"));
  PlaneOptions uniform, graded;
  uniform.max_size = graded.max_size = 0.2;
  graded.sizing_file = dir / "sizing.txt";
  const PlaneMesh a = mesh_plane(domain, uniform), b = mesh_plane(domain, graded);
  expect_conforming(b, measure_plane_quality(b));
  const auto near_origin = [](const PlaneMesh& m) {
    return std::count_if(m.cells.begin(), m.cells.end(), [](const PlaneCell& c) { return c.centroid.norm() < 0.25; });
  };
  EXPECT_GT(near_origin(b), 3 * near_origin(a));
}

TEST(MeshPlane, TheSameSeedGivesTheSameMeshOnAnyNumberOfThreads) {
  const PlanarDomain domain = read_planar_domain(test::sample_2d("cross_section.poly"));
  PlaneOptions one, two;
  one.max_size = two.max_size = 0.3;
  one.threads = 1;
  two.threads = 2;
  const PlaneMesh a = mesh_plane(domain, one), b = mesh_plane(domain, two);
  ASSERT_EQ(a.points.size(), b.points.size());
  ASSERT_EQ(a.cells.size(), b.cells.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) EXPECT_EQ(a.points[i], b.points[i]);
  for (std::size_t c = 0; c < a.cells.size(); ++c) EXPECT_EQ(a.cells[c].points, b.cells[c].points);
  // Another seed, other interior seeds; the boundary's stay.
  PlaneOptions other = one;
  other.seed = 7;
  const PlaneMesh c = mesh_plane(domain, other);
  EXPECT_NE(c.points.size() == a.points.size() && c.points == a.points, true);
}

}  // namespace
}  // namespace vorocrust
