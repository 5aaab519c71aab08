// Checks of a VoronoiMesh that share no code with the library: closed convex cells, faces listed
// once and shared by exactly their two cells, volumes against the divergence theorem over the
// boundary, the Voronoi property of every face.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "vorocrust/cells.hpp"

namespace vorocrust::test {

// The polygon of face f as cell c sees it: outward.
inline std::vector<Index> outward(const VoronoiMesh& m, std::size_t c, Index f) {
  std::vector<Index> p = m.faces[f].points;
  if (m.faces[f].owner != static_cast<std::int32_t>(c)) std::reverse(p.begin(), p.end());
  return p;
}

inline Point area_vector(const VoronoiMesh& m, const std::vector<Index>& polygon) {
  Point centre = Point::Zero();
  for (Index p : polygon) centre += m.points[p];
  centre /= static_cast<double>(polygon.size());
  Point area = Point::Zero();
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    area += 0.5 * (m.points[polygon[k]] - centre).cross(m.points[polygon[(k + 1) % polygon.size()]] - centre);
  }
  return area;
}

// Volume enclosed by the boundary faces (those with no cell across), by the divergence theorem
// over their triangles fanned about their vertex means.
inline double volume_inside_boundary(const VoronoiMesh& m) {
  double volume = 0;
  for (const VoronoiFace& f : m.faces) {
    if (f.neighbour != kNoCell) continue;
    Point centre = Point::Zero();
    for (Index p : f.points) centre += m.points[p];
    centre /= static_cast<double>(f.points.size());
    for (std::size_t k = 0; k < f.points.size(); ++k) {
      volume += centre.dot((m.points[f.points[k]] - centre).cross(m.points[f.points[(k + 1) % f.points.size()]] - centre)) / 6;
    }
  }
  return volume;
}

inline void expect_closed_and_convex(const VoronoiMesh& m, double tolerance) {
  for (std::size_t c = 0; c < m.cells.size(); ++c) {
    std::map<std::pair<Index, Index>, int> edges;
    std::set<Index> points;
    for (Index f : m.cells[c].faces) {
      const std::vector<Index> p = outward(m, c, f);
      for (std::size_t k = 0; k < p.size(); ++k) ++edges[{p[k], p[(k + 1) % p.size()]}], points.insert(p[k]);
    }
    for (const auto& [e, uses] : edges) {
      ASSERT_EQ(uses, 1) << "cell " << c << " uses an edge twice in one direction";
      ASSERT_EQ(edges.count({e.second, e.first}), 1u) << "cell " << c << " is open at an edge";
    }
    for (Index f : m.cells[c].faces) {
      const std::vector<Index> p = outward(m, c, f);
      const Point n = area_vector(m, p).normalized();
      const double offset = n.dot(m.points[p[0]]);
      for (Index q : points) ASSERT_LE(n.dot(m.points[q]) - offset, tolerance) << "cell " << c << " is not convex";
    }
  }
}

inline void expect_faces_shared_once(const VoronoiMesh& m, const std::vector<Seed>& seeds) {
  std::set<std::pair<std::int32_t, std::int32_t>> pairs;
  std::vector<int> uses(m.faces.size(), 0);
  for (std::size_t c = 0; c < m.cells.size(); ++c) {
    for (Index f : m.cells[c].faces) ++uses[f];
  }
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const VoronoiFace& face = m.faces[f];
    const bool interior = face.neighbour != kNoCell;
    ASSERT_EQ(uses[f], interior ? 2 : 1) << "face " << f;
    ASSERT_EQ(m.cells[face.owner].seed, face.owner_seed);
    ASSERT_EQ(face.regions.back, seeds[face.owner_seed].region);
    ASSERT_EQ(face.regions.front, seeds[face.neighbour_seed].region);
    // Normal from owner to the other side: along the link between their seeds.
    const Point link = seeds[face.neighbour_seed].position - seeds[face.owner_seed].position;
    ASSERT_GT(area_vector(m, face.points).dot(link), 0) << "face " << f << " points into its owner";
    if (!interior) continue;
    ASSERT_LT(face.owner, face.neighbour);
    ASSERT_EQ(m.cells[face.neighbour].seed, face.neighbour_seed);
    ASSERT_TRUE(pairs.insert({face.owner, face.neighbour}).second) << "two faces between cells " << face.owner
                                                                    << " and " << face.neighbour;
  }
}

// Every face point is equidistant from the two seeds the face separates, and the face is
// orthogonal to their link. Returns the largest relative distance difference and the largest
// angle (radians) between a face normal and its link.
inline std::pair<double, double> voronoi_deviation(const VoronoiMesh& m, const std::vector<Seed>& seeds) {
  double distance = 0, angle = 0;
  for (const VoronoiFace& f : m.faces) {
    const Point a = seeds[f.owner_seed].position, b = seeds[f.neighbour_seed].position;
    for (Index p : f.points) {
      const double da = (m.points[p] - a).norm(), db = (m.points[p] - b).norm();
      distance = std::max(distance, std::abs(da - db) / (b - a).norm());
    }
    const Point area = area_vector(m, f.points);
    if (area.norm() < 1e-6 * (b - a).squaredNorm()) continue;  // a sliver face's normal says little
    angle = std::max(angle, std::acos(std::clamp(area.normalized().dot((b - a).normalized()), -1.0, 1.0)));
  }
  return {distance, angle};
}

// No seed is nearer to a cell's points than the cell's own seed: the cells are Voronoi cells.
inline void expect_empty_spheres(const VoronoiMesh& m, const std::vector<Seed>& seeds) {
  std::vector<double> radius(m.points.size(), -1);
  for (const VoronoiCell& c : m.cells) {
    for (Index f : c.faces) {
      for (Index p : m.faces[f].points) radius[p] = (m.points[p] - seeds[c.seed].position).norm();
    }
  }
  for (std::size_t p = 0; p < m.points.size(); ++p) {
    for (const Seed& s : seeds) {
      ASSERT_GE((m.points[p] - s.position).norm(), radius[p] * (1 - 1e-9)) << "point " << p;
    }
  }
}

// distance_tolerance bounds how far a point may be from equidistant to a face's two seeds, relative
// to their distance: seeds closer than a millionth of their coordinates leave only a few digits.
inline void expect_valid(const VoronoiMesh& m, const std::vector<Seed>& seeds, double distance_tolerance = 1e-9) {
  ASSERT_FALSE(m.cells.empty());
  expect_closed_and_convex(m, 1e-9);
  expect_faces_shared_once(m, seeds);
  const double inside = volume_inside_boundary(m);
  EXPECT_NEAR(total_volume(m), inside, 1e-9 * inside);
  const auto [distance, angle] = voronoi_deviation(m, seeds);
  EXPECT_LT(distance, distance_tolerance);
  EXPECT_LT(angle, 1e-6);
}

}  // namespace vorocrust::test
