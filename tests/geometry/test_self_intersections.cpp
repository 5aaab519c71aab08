// find_self_intersections on meshes built in code: closed surfaces that must report nothing
// (however many faces share vertices and edges), crafted intersections with known answers, and
// random soups where the tree-pruned search must find exactly what testing all pairs finds.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <numbers>
#include <random>
#include <vector>

#include "geometry/self_intersections.hpp"
#include "geometry/triangle_intersection.hpp"

namespace vorocrust::geometry {
namespace {

using Pairs = std::vector<FacePair>;

SurfaceMesh make_mesh(std::vector<Point> vertices, std::vector<Triangle> triangles) {
  SurfaceMesh mesh;
  mesh.vertices = std::move(vertices);
  mesh.triangles = std::move(triangles);
  return mesh;
}

// Adds a triangle on three new vertices (sharing nothing by index).
void add_free_triangle(SurfaceMesh& mesh, const Point& a, const Point& b, const Point& c) {
  const auto first = static_cast<Index>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), {a, b, c});
  mesh.triangles.push_back({first, first + 1, first + 2});
}

// The unit cube; vertex x + 2y + 4z is corner (x, y, z). Faces 0-1 are x = 0 (face 0 the half
// y >= z), 2-3 are x = 1 (face 2 the half y >= z), 4-5 y = 0, 6-7 y = 1, 8-9 z = 0, 10-11 z = 1
// (split along the diagonal from vertex 4 to vertex 7).
SurfaceMesh unit_cube() {
  std::vector<Point> vertices;
  for (int i = 0; i < 8; ++i) vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  return make_mesh(vertices, {{0, 6, 2},
                              {0, 4, 6},
                              {1, 3, 7},
                              {1, 7, 5},
                              {0, 1, 5},
                              {0, 5, 4},
                              {2, 7, 3},
                              {2, 6, 7},
                              {0, 2, 3},
                              {0, 3, 1},
                              {4, 5, 7},
                              {4, 7, 6}});
}

// A closed UV sphere: 2 * slices * (stacks - 1) faces, fans at the poles.
SurfaceMesh uv_sphere(int slices, int stacks) {
  SurfaceMesh mesh;
  mesh.vertices.emplace_back(0, 0, 1);
  for (int k = 1; k < stacks; ++k) {
    const double theta = std::numbers::pi * k / stacks;
    for (int i = 0; i < slices; ++i) {
      const double phi = 2 * std::numbers::pi * i / slices;
      mesh.vertices.emplace_back(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                                 std::cos(theta));
    }
  }
  mesh.vertices.emplace_back(0, 0, -1);
  const auto south = static_cast<Index>(mesh.vertices.size() - 1);
  auto ring = [&](int k, int i) { return static_cast<Index>(1 + (k - 1) * slices + i % slices); };
  for (int i = 0; i < slices; ++i) {
    mesh.triangles.push_back({0, ring(1, i), ring(1, i + 1)});
    for (int k = 1; k + 1 < stacks; ++k) {
      mesh.triangles.push_back({ring(k, i), ring(k + 1, i), ring(k + 1, i + 1)});
      mesh.triangles.push_back({ring(k, i), ring(k + 1, i + 1), ring(k, i + 1)});
    }
    mesh.triangles.push_back({south, ring(stacks - 1, i + 1), ring(stacks - 1, i)});
  }
  return mesh;
}

// The surface of the cube [0, n]^3 cut into 2 n^2 triangles per side, mapped through `place`:
// neighbouring faces of a side are coplanar (exactly so when `place` keeps planes exact).
template <class Place>
SurfaceMesh subdivided_cube(int n, Place place) {
  SurfaceMesh mesh;
  std::map<std::array<int, 3>, Index> index;
  auto vertex = [&](const std::array<int, 3>& g) {
    auto [it, added] = index.try_emplace(g, static_cast<Index>(mesh.vertices.size()));
    if (added) mesh.vertices.push_back(place(Point(g[0], g[1], g[2])));
    return it->second;
  };
  for (int d = 0; d < 3; ++d)
    for (int side : {0, n})
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          auto grid = [&](int i, int j) {
            std::array<int, 3> g;
            g[d] = side, g[(d + 1) % 3] = i, g[(d + 2) % 3] = j;
            return vertex(g);
          };
          const Index p = grid(a, b), q = grid(a + 1, b), r = grid(a + 1, b + 1),
                      s = grid(a, b + 1);
          if ((a + b) % 2 == 0) {
            mesh.triangles.push_back({p, q, r});
            mesh.triangles.push_back({p, r, s});
          } else {
            mesh.triangles.push_back({p, q, s});
            mesh.triangles.push_back({q, r, s});
          }
        }
  return mesh;
}

// All pairs, no spatial index: the reference the tree search must reproduce.
Pairs all_pairs_reference(const SurfaceMesh& mesh) {
  Pairs pairs;
  auto corners = [&](std::size_t f) {
    const Triangle& t = mesh.triangles[f];
    return TriangleCorners{mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
  };
  for (std::size_t i = 0; i < mesh.num_faces(); ++i)
    for (std::size_t j = i + 1; j < mesh.num_faces(); ++j)
      if (improperly_intersect(corners(i), corners(j),
                               shared_corners(mesh.triangles[i], mesh.triangles[j])))
        pairs.emplace_back(i, j);
  return pairs;
}

TEST(SelfIntersections, ClosedCubeHasNone) {
  EXPECT_TRUE(find_self_intersections(unit_cube()).empty());
}

TEST(SelfIntersections, EmptyMeshAndBadIndices) {
  EXPECT_TRUE(find_self_intersections(SurfaceMesh{}).empty());
  SurfaceMesh mesh = unit_cube();
  mesh.triangles.push_back({0, 7, 99});  // out of range: another check's business
  EXPECT_TRUE(find_self_intersections(mesh).empty());
}

TEST(SelfIntersections, CubePiercedByATriangle) {
  SurfaceMesh mesh = unit_cube();
  // In the plane y = 0.8, entering through x = 0 and leaving through x = 1 where y > z.
  add_free_triangle(mesh, Point(-1, 0.8, 0.15), Point(2, 0.8, 0.15), Point(2, 0.8, 0.25));
  EXPECT_EQ(find_self_intersections(mesh), (Pairs{{0, 12}, {2, 12}}));
}

TEST(SelfIntersections, TouchingCountsAndNearMissDoesNot) {
  // A triangle standing on the top face's diagonal: it touches faces 10 and 11 at one point.
  SurfaceMesh touching = unit_cube();
  add_free_triangle(touching, Point(0.5, 0.5, 1), Point(0, 0, 2), Point(1, 0, 2));
  EXPECT_EQ(find_self_intersections(touching), (Pairs{{10, 12}, {11, 12}}));
  SurfaceMesh apart = unit_cube();
  add_free_triangle(apart, Point(0.5, 0.5, 1 + 0x1p-52), Point(0, 0, 2), Point(1, 0, 2));
  EXPECT_TRUE(find_self_intersections(apart).empty());
}

TEST(SelfIntersections, TwoOverlappingTetrahedra) {
  std::vector<Point> vertices = {Point(0, 0, 0), Point(2, 0, 0), Point(0, 2, 0), Point(0, 0, 2)};
  for (int i = 0; i < 4; ++i) vertices.push_back(vertices[i] + Point(0.5, 0.5, 0.5));
  const SurfaceMesh mesh = make_mesh(
      vertices,
      {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {4, 6, 5}, {4, 5, 7}, {4, 7, 6}, {5, 6, 7}});
  // B's corner (0.5, 0.5, 0.5) is inside A: B's three faces there cross A's slanted face; B's
  // slanted face is parallel to A's and beyond it, and B misses A's axis-aligned faces.
  const Pairs expected = {{3, 4}, {3, 5}, {3, 6}};
  EXPECT_EQ(find_self_intersections(mesh), expected);
  EXPECT_EQ(all_pairs_reference(mesh), expected);
}

TEST(SelfIntersections, DuplicateAndDegenerateFacesAreNotReported) {
  SurfaceMesh mesh = unit_cube();
  mesh.triangles.push_back({6, 2, 0});  // face 0 again, in another corner order
  mesh.triangles.push_back({0, 2, 6});  // face 0 flipped
  mesh.triangles.push_back({0, 7, 7});  // repeated index
  mesh.vertices.push_back(Point(0.5, 0.5, 0.5));
  mesh.triangles.push_back({0, 8, 7});  // collinear through the cube's centre
  EXPECT_TRUE(find_self_intersections(mesh).empty());
}

TEST(SelfIntersections, UvSphereOf20000FacesHasNone) {
  const SurfaceMesh sphere = uv_sphere(100, 101);
  ASSERT_EQ(sphere.num_faces(), 20000u);
  double best_ms = 1e300;
  Pairs found;
  for (int run = 0; run < 5; ++run) {
    const auto start = std::chrono::steady_clock::now();
    found = find_self_intersections(sphere);
    const std::chrono::duration<double, std::milli> elapsed =
        std::chrono::steady_clock::now() - start;
    best_ms = std::min(best_ms, elapsed.count());
  }
  EXPECT_TRUE(found.empty()) << found.size() << " pairs, first " << found[0].first << " "
                             << found[0].second;
  std::cout << "[ timing ] find_self_intersections, 20000-face UV sphere: " << best_ms
            << " ms (best of 5)\n";
  RecordProperty("sphere_20k_ms", std::to_string(best_ms));
}

TEST(SelfIntersections, SubdividedCubesWithCoplanarNeighboursHaveNone) {
  // Exactly coplanar neighbours, on ugly coordinates (multiples of 0.1 are inexact, but each
  // side keeps one coordinate constant so its plane is exact).
  const SurfaceMesh flat = subdivided_cube(40, [](const Point& g) { return Point(0.1 * g); });
  ASSERT_EQ(flat.num_faces(), 6u * 2 * 40 * 40);
  EXPECT_TRUE(find_self_intersections(flat).empty());
  // Rotated: neighbours are now coplanar only up to rounding, so the exact path decides.
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const SurfaceMesh turned = subdivided_cube(
      40, [&](const Point& g) { return Point(rotation * (0.1 * g) + Point(1e3, -7, 0.3)); });
  EXPECT_TRUE(find_self_intersections(turned).empty());
}

TEST(SelfIntersections, SphereWithAVertexPushedThroughIt) {
  SurfaceMesh mesh = uv_sphere(40, 21);
  // Push one ring vertex through the opposite side of the sphere: its faces now cross others.
  const Index moved = 1 + 9 * 40 + 5;
  mesh.vertices[moved] = -1.5 * mesh.vertices[moved];
  const Pairs found = find_self_intersections(mesh);
  EXPECT_FALSE(found.empty());
  EXPECT_EQ(found, all_pairs_reference(mesh));
  for (const FacePair& pair : found) {
    const Triangle &t = mesh.triangles[pair.first], &u = mesh.triangles[pair.second];
    const bool touches_moved =
        std::count(t.begin(), t.end(), moved) + std::count(u.begin(), u.end(), moved) > 0;
    EXPECT_TRUE(touches_moved) << pair.first << " " << pair.second;
  }
}

// Random soups: large crossing triangles sharing vertices from a small pool, and small
// triangles on a coarse grid (welded, so full of shared vertices, coplanarity and touching).
TEST(SelfIntersections, RandomSoupsMatchAllPairs) {
  std::mt19937_64 rng(99);
  {
    std::uniform_real_distribution<double> coordinate(0, 1);
    std::vector<Point> vertices;
    for (int i = 0; i < 150; ++i)
      vertices.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
    std::uniform_int_distribution<Index> pick(0, 149);
    std::vector<Triangle> triangles;
    while (triangles.size() < 250) {
      const Triangle t = {pick(rng), pick(rng), pick(rng)};
      if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) triangles.push_back(t);
    }
    for (int i = 0; i < 10; ++i) {
      const Triangle t = triangles[static_cast<std::size_t>(i) * 7];
      triangles.push_back(i % 2 ? Triangle{t[2], t[1], t[0]} : Triangle{t[1], t[2], t[0]});
    }
    const SurfaceMesh mesh = make_mesh(vertices, triangles);
    const Pairs found = find_self_intersections(mesh);
    EXPECT_GT(found.size(), 1000u);
    EXPECT_EQ(found, all_pairs_reference(mesh));
  }
  {
    std::uniform_int_distribution<int> cell(0, 24), offset(-1, 1);
    std::map<std::array<int, 3>, Index> index;
    std::vector<Point> vertices;
    auto vertex = [&](const std::array<int, 3>& g) {
      auto [it, added] = index.try_emplace(g, static_cast<Index>(vertices.size()));
      if (added) vertices.emplace_back(0.25 * g[0], 0.25 * g[1], 0.25 * g[2]);
      return it->second;
    };
    std::vector<Triangle> triangles;
    for (int f = 0; f < 3000; ++f) {
      const std::array<int, 3> centre = {cell(rng), cell(rng), cell(rng)};
      Triangle t;
      for (Index& corner : t)
        corner =
            vertex({centre[0] + offset(rng), centre[1] + offset(rng), centre[2] + offset(rng)});
      triangles.push_back(t);
    }
    const SurfaceMesh mesh = make_mesh(vertices, triangles);
    const Pairs found = find_self_intersections(mesh);
    EXPECT_GT(found.size(), 100u);
    EXPECT_EQ(found, all_pairs_reference(mesh));
    EXPECT_EQ(find_self_intersections(mesh), found);  // deterministic
    for (std::size_t k = 0; k < found.size(); ++k) {
      EXPECT_LT(found[k].first, found[k].second);
      if (k > 0) {
        EXPECT_LT(found[k - 1], found[k]);
      }
    }
  }
}

}  // namespace
}  // namespace vorocrust::geometry
