// Clipped cells on built domains, checked by means that share no code with the clipping: volumes
// that add up to the domain's, closed cells, boundary faces that cover the input's area, faces
// between cells on their seeds' bisectors, and random points of the domain in the cell of their
// nearest seed (by each cell's winding number about the point).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <tuple>
#include <vector>

#include "clipping/clip_cells.hpp"
#include "surface_builder.hpp"
#include "vorocrust/cells.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/regions.hpp"

namespace vorocrust {
namespace {

struct Domain {
  SurfaceMesh surface;
  Point lo, hi;            // the outer box
  Point void_lo, void_hi;  // a cavity, empty when void_lo > void_hi
  bool inside(const Point& p) const {
    const bool in_box = (p.array() > lo.array()).all() && (p.array() < hi.array()).all();
    const bool in_void = (p.array() >= void_lo.array()).all() && (p.array() <= void_hi.array()).all();
    return in_box && !in_void;
  }
  double volume() const {
    const Point v = (void_hi - void_lo).cwiseMax(0.0);
    return (hi - lo).prod() - v.prod();
  }
};

// A box, with a cavity when `cavity` is given: the cavity's sides face into it, so it is outside.
Domain box_domain(const Point& lo, const Point& hi, const Point& cavity_lo = Point::Ones(),
                  const Point& cavity_hi = Point::Zero()) {
  test::SurfaceBuilder b;
  b.box(lo, hi);
  const bool has_cavity = (cavity_lo.array() < cavity_hi.array()).all();
  if (has_cavity) {
    const std::size_t first = b.mesh.triangles.size();
    b.box(cavity_lo, cavity_hi);
    for (std::size_t t = first; t < b.mesh.triangles.size(); ++t)
      std::swap(b.mesh.triangles[t][1], b.mesh.triangles[t][2]);
  }
  Domain d{b.mesh, lo, hi, cavity_lo, cavity_hi};
  label_regions(d.surface);
  return d;
}

// `n` seeds uniform in the domain, then outside seeds on a box `margin` beyond it.
std::vector<Seed> seeds_in(const Domain& d, int n, double margin, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Seed> seeds;
  while (static_cast<int>(seeds.size()) < n) {
    const Point p = d.lo + (d.hi - d.lo).cwiseProduct(Point(u(random), u(random), u(random)));
    if (d.inside(p)) seeds.push_back({p, 1, 0, SeedKind::Interior});
  }
  const Point lo = d.lo - Point::Constant(margin), hi = d.hi + Point::Constant(margin);
  const int k = 6;
  for (int i = 0; i <= k; ++i) {
    for (int j = 0; j <= k; ++j) {
      for (int l = 0; l <= k; ++l) {
        if (i != 0 && i != k && j != 0 && j != k && l != 0 && l != k) continue;
        const Point t(i / double(k), j / double(k), l / double(k));
        seeds.push_back({lo + (hi - lo).cwiseProduct(t), 0, 0, SeedKind::Outside});
      }
    }
  }
  return seeds;
}

// Face f's polygon as cell c sees it: outward.
std::vector<Point> outward(const VoronoiMesh& m, std::size_t c, Index f) {
  std::vector<Point> polygon;
  for (Index p : m.faces[f].points) polygon.push_back(m.points[p]);
  if (m.faces[f].owner != static_cast<std::int32_t>(c)) std::reverse(polygon.begin(), polygon.end());
  return polygon;
}

// The solid angle of cell c's boundary about q, over 4 pi: 1 inside the cell, 0 outside.
double winding_number(const VoronoiMesh& m, std::size_t c, const Point& q) {
  double sum = 0;
  for (Index f : m.cells[c].faces) {
    const std::vector<Point> polygon = outward(m, c, f);
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
      const Point a = polygon[0] - q, b = polygon[k] - q, d = polygon[k + 1] - q;
      const double la = a.norm(), lb = b.norm(), ld = d.norm();
      sum += 2 * std::atan2(a.dot(b.cross(d)), la * lb * ld + a.dot(b) * ld + a.dot(d) * lb + b.dot(d) * la);
    }
  }
  return sum / (4 * M_PI);
}

void expect_closed(const VoronoiMesh& m) {
  for (std::size_t c = 0; c < m.cells.size(); ++c) {
    std::map<std::pair<Index, Index>, int> edges;
    for (Index f : m.cells[c].faces) {
      std::vector<Index> polygon = m.faces[f].points;
      if (m.faces[f].owner != static_cast<std::int32_t>(c)) std::reverse(polygon.begin(), polygon.end());
      for (std::size_t k = 0; k < polygon.size(); ++k) ++edges[{polygon[k], polygon[(k + 1) % polygon.size()]}];
    }
    for (const auto& [e, count] : edges) {
      ASSERT_EQ(count, 1) << "cell " << c;
      ASSERT_EQ(edges.count({e.second, e.first}), 1u) << "cell " << c << " is open at an edge";
    }
  }
}

void expect_clipped(const Domain& d, const std::vector<Seed>& seeds, const VoronoiMesh& clipped) {
  double volume = 0, boundary_area = 0;
  for (const VoronoiCell& c : clipped.cells) {
    EXPECT_GT(c.volume, 0);
    volume += c.volume;
  }
  EXPECT_NEAR(volume, d.volume(), 1e-12 * d.volume());
  expect_closed(clipped);
  for (std::size_t f = 0; f < clipped.faces.size(); ++f) {
    const VoronoiFace& face = clipped.faces[f];
    const FaceGeometry g = face_geometry(clipped, f);
    if (face.neighbour == kNoCell) {
      boundary_area += g.area;
      continue;
    }
    // Faces between cells stay on their seeds' bisector.
    const Point link = (seeds[face.neighbour_seed].position - seeds[face.owner_seed].position).normalized();
    EXPECT_GT(g.normal.dot(link), 1 - 1e-9);
    for (Index p : face.points) {
      const Point& x = clipped.points[p];
      EXPECT_NEAR((x - seeds[face.owner_seed].position).norm(), (x - seeds[face.neighbour_seed].position).norm(), 1e-9);
    }
  }
  const Point side = d.hi - d.lo, hollow = (d.void_hi - d.void_lo).cwiseMax(0.0);
  const auto area = [](const Point& s) { return 2 * (s.x() * s.y() + s.y() * s.z() + s.z() * s.x()); };
  EXPECT_NEAR(boundary_area, area(side) + area(hollow), 1e-12 * area(side));
  // Random points lie in the cell of their nearest seed, and in no other.
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 300; ++trial) {
    const Point q = d.lo + side.cwiseProduct(Point(u(random), u(random), u(random)));
    if (!d.inside(q)) continue;
    std::size_t nearest = 0, other = 1;
    for (std::size_t c = 0; c < clipped.cells.size(); ++c) {
      const double dc = (seeds[clipped.cells[c].seed].position - q).norm();
      if (dc < (seeds[clipped.cells[nearest].seed].position - q).norm()) {
        other = nearest;
        nearest = c;
      } else if (c != nearest && dc < (seeds[clipped.cells[other].seed].position - q).norm()) {
        other = c;
      }
    }
    EXPECT_NEAR(winding_number(clipped, nearest, q), 1, 1e-6);
    EXPECT_NEAR(winding_number(clipped, other, q), 0, 1e-6);
  }
}

TEST(ClipCells, CubeCellsAddUpToTheCube) {
  const Domain d = box_domain(Point::Zero(), Point::Ones());
  const std::vector<Seed> seeds = seeds_in(d, 300, 1.0, 3);
  const VoronoiMesh voronoi = compute_cells(seeds);
  ClippingStats stats;
  const VoronoiMesh clipped = clipping::clip_cells(voronoi, d.surface, &stats);
  ASSERT_EQ(clipped.cells.size(), 300u);
  expect_clipped(d, seeds, clipped);
  EXPECT_GT(stats.clipped_cells, 100u);
  EXPECT_LT(stats.clipped_cells, 300u);
  // Cells the surface does not reach are the Voronoi cells as they were.
  std::size_t kept = 0;
  for (std::size_t c = 0; c < clipped.cells.size(); ++c) {
    const bool boundary = std::any_of(clipped.cells[c].faces.begin(), clipped.cells[c].faces.end(),
                                      [&](Index f) { return clipped.faces[f].neighbour == kNoCell; });
    if (boundary) continue;
    EXPECT_NEAR(clipped.cells[c].volume, voronoi.cells[c].volume, 1e-12);
    ++kept;
  }
  EXPECT_EQ(kept + stats.clipped_cells, 300u);
  // A cell's part of one side of the cube is one face, whatever the triangles under it.
  EXPECT_GT(stats.surface_pieces, 0u);
  for (std::size_t c = 0; c < clipped.cells.size(); ++c) {
    std::set<std::tuple<long, long, long>> sides;
    for (Index f : clipped.cells[c].faces) {
      if (clipped.faces[f].neighbour != kNoCell) continue;
      const Point n = face_geometry(clipped, f).normal;
      EXPECT_NEAR(n.cwiseAbs().maxCoeff(), 1, 1e-12);
      EXPECT_TRUE(sides.emplace(std::lround(n.x()), std::lround(n.y()), std::lround(n.z())).second) << "cell " << c;
    }
  }
}

TEST(ClipCells, CellsAboutACavityAreNotConvexAndStillAddUp) {
  const Domain d = box_domain(Point::Zero(), Point(2, 1, 1), Point(0.7, 0.3, 0.35), Point(1.3, 0.7, 0.65));
  const std::vector<Seed> seeds = seeds_in(d, 500, 1.5, 5);
  ClippingStats stats;
  const VoronoiMesh clipped = clipping::clip_cells(compute_cells(seeds), d.surface, &stats);
  expect_clipped(d, seeds, clipped);
  // The cavity's corners poke through faces: their parts have holes, cut out.
  EXPECT_GT(stats.holes, 0u);
}

// One layer of seeds low in the cube: their cells are columns, neighbours at every height, so the
// top triangles are cut among them as among neighbours, yet the top is nearer the outside seeds a
// tenth above it than any seed. The clipping reports the top uncovered (clipped_cells then moves
// the outside seeds away); with the outside seeds far away the same seeds clip to the cube.
TEST(ClipCells, SurfaceNearerOutsideSeedsIsUncovered) {
  const Domain d = box_domain(Point::Zero(), Point::Ones());
  std::mt19937_64 random(8);
  std::uniform_real_distribution<double> move(-1e-3, 1e-3);
  for (const double margin : {0.1, 3.0}) {
    std::vector<Seed> seeds;
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) {
        seeds.push_back({Point(0.125 + 0.25 * i + move(random), 0.125 + 0.25 * j + move(random), 0.2 + move(random)), 1,
                         0, SeedKind::Interior});
      }
    }
    for (const Seed& s : seeds_in(d, 0, margin, 4)) seeds.push_back(s);
    ClippingStats stats;
    const VoronoiMesh clipped = clipping::clip_cells(compute_cells(seeds), d.surface, &stats);
    if (margin < 1) {
      EXPECT_GE(stats.uncovered_triangles, 2u);
      EXPECT_TRUE(clipped.cells.empty());
    } else {
      EXPECT_EQ(stats.uncovered_triangles, 0u);
      expect_clipped(d, seeds, clipped);
    }
  }
}

TEST(ClipCells, IsTheSameOnEveryRun) {
  const Domain d = box_domain(Point::Zero(), Point::Ones());
  const std::vector<Seed> seeds = seeds_in(d, 200, 1.0, 9);
  const VoronoiMesh a = clipping::clip_cells(compute_cells(seeds), d.surface);
  const VoronoiMesh b = clipping::clip_cells(compute_cells(seeds), d.surface);
  ASSERT_EQ(a.points, b.points);
  ASSERT_EQ(a.faces.size(), b.faces.size());
  for (std::size_t f = 0; f < a.faces.size(); ++f) EXPECT_EQ(a.faces[f].points, b.faces[f].points);
}

// Two unit cubes side by side, x < 1 one material and x > 1 another: their common side is an
// interface, cut by both materials' cells.
TEST(ClipCells, TwoMaterialsMeetOnTheirInterface) {
  test::SurfaceBuilder b;
  b.box(Point::Zero(), Point::Ones(), /*skip_high_x=*/true);
  b.box(Point(1, 0, 0), Point(2, 1, 1));
  SurfaceMesh surface = b.mesh;
  label_regions(surface);
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Seed> seeds;
  std::array<std::int32_t, 2> material{};
  for (int side = 0; side < 2; ++side) {
    // The regions' labels, from the side of the wall each region's faces face.
    for (std::size_t t = 0; t < surface.num_faces(); ++t) {
      const Triangle& tri = surface.triangles[t];
      const Point c = (surface.vertices[tri[0]] + surface.vertices[tri[1]] + surface.vertices[tri[2]]) / 3;
      if (std::abs(c.x() - 1) < 1e-12) continue;
      const bool left = c.x() < 1;
      if (left == (side == 0)) material[side] = std::max(surface.face_regions[t].back, surface.face_regions[t].front);
    }
    for (int k = 0; k < 150; ++k) {
      seeds.push_back({Point(side + u(random), u(random), u(random)), material[side], 0, SeedKind::Interior});
    }
  }
  ASSERT_NE(material[0], material[1]);
  ASSERT_GT(material[0], 0);
  ASSERT_GT(material[1], 0);
  const std::size_t materials_end = seeds.size();
  const Domain far = box_domain(Point(-1, -1, -1), Point(3, 2, 2));
  for (const Seed& s : seeds_in(far, 0, 0, 1)) seeds.push_back(s);
  ClippingStats stats;
  const VoronoiMesh m = clipping::clip_cells(clipping::material_diagrams(seeds, materials_end), surface, &stats);
  ASSERT_EQ(m.cells.size(), materials_end);
  expect_closed(m);
  std::map<std::int32_t, double> volume;
  for (const VoronoiCell& c : m.cells) volume[c.region] += c.volume;
  EXPECT_NEAR(volume[material[0]], 1, 1e-12);
  EXPECT_NEAR(volume[material[1]], 1, 1e-12);
  double wall = 0, outer = 0;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const VoronoiFace& face = m.faces[f];
    const double area = face_geometry(m, f).area;
    if (face.neighbour == kNoCell) {
      outer += area;
      continue;
    }
    const std::int32_t a = m.cells[face.owner].region, c = m.cells[face.neighbour].region;
    EXPECT_EQ(face.regions.back, a);
    EXPECT_EQ(face.regions.front, c);
    if (a == c) {
      // Faces within a material stay on their seeds' bisector.
      for (Index p : face.points) {
        const Point& x = m.points[p];
        EXPECT_NEAR((x - seeds[face.owner_seed].position).norm(), (x - seeds[face.neighbour_seed].position).norm(),
                    1e-9);
      }
      continue;
    }
    wall += area;
    for (Index p : face.points) EXPECT_NEAR(m.points[p].x(), 1, 1e-12);
  }
  EXPECT_NEAR(wall, 1, 1e-12);
  EXPECT_NEAR(outer, 10, 1e-11);
  EXPECT_GT(stats.surface_pieces, 0u);
  // Random points lie in the cell of their material's nearest seed.
  for (int trial = 0; trial < 200; ++trial) {
    const Point q(2 * u(random), u(random), u(random));
    const std::int32_t own = material[q.x() < 1 ? 0 : 1];
    std::size_t nearest = m.cells.size();
    for (std::size_t c = 0; c < m.cells.size(); ++c) {
      if (m.cells[c].region != own) continue;
      if (nearest == m.cells.size() || (m.cells[c].site - q).norm() < (m.cells[nearest].site - q).norm()) nearest = c;
    }
    EXPECT_NEAR(winding_number(m, nearest, q), 1, 1e-6) << "point " << q.transpose();
  }
}

}  // namespace
}  // namespace vorocrust
