// The volume quality on cells whose figures are known exactly: hand-made polyhedra, the cubes of
// the cubic lattice, the truncated octahedra of the BCC lattice and the rhombic dodecahedra of
// the FCC lattice; then the properties any cell must have, the summary figures, thread
// independence and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <set>
#include <tuple>

#include "cells/seed_sets.hpp"
#include "geometry/brute_force_spheres.hpp"
#include "vorocrust/cell_quality.hpp"
#include "test_support.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/mesher.hpp"
#include "vorocrust/read_mesh.hpp"

namespace vorocrust {
namespace {

// One closed box [0, a] x [0, b] x [0, c] as a one-cell mesh, faces outward.
VoronoiMesh box_mesh(double a, double b, double c) {
  VoronoiMesh m;
  for (int i = 0; i < 8; ++i) m.points.emplace_back(a * (i & 1), b * ((i >> 1) & 1), c * ((i >> 2) & 1));
  const std::vector<std::vector<Index>> faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                                 {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  VoronoiCell cell;
  cell.seed = 7;
  cell.region = 1;
  cell.volume = a * b * c;
  for (const auto& polygon : faces) {
    VoronoiFace f;
    f.points = polygon;
    f.owner = 0;
    cell.faces.push_back(static_cast<Index>(m.faces.size()));
    m.faces.push_back(f);
  }
  m.cells.push_back(cell);
  return m;
}

// The regular tetrahedron of edge 2 sqrt(2), inside the cube [-1, 1]^3.
VoronoiMesh tetrahedron_mesh() {
  VoronoiMesh m;
  m.points = {Point(1, 1, 1), Point(1, -1, -1), Point(-1, 1, -1), Point(-1, -1, 1)};
  VoronoiCell cell;
  cell.volume = 8.0 / 3;
  for (const std::vector<Index>& polygon : std::vector<std::vector<Index>>{{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}) {
    VoronoiFace f;
    f.points = polygon;
    f.owner = 0;  // every face has its owner cell (AddressSanitizer caught the skewness reading cell -1)
    cell.faces.push_back(static_cast<Index>(m.faces.size()));
    m.faces.push_back(f);
  }
  m.cells.push_back(cell);
  return m;
}

TEST(CellQuality, HandMadePolyhedra) {
  // A box 1 x 1 x 2: R = sqrt(6) / 2, r = 1/2, shortest edge 1 against a size of cbrt(2).
  CellQuality q = measure_cell_quality(box_mesh(1, 1, 2));
  ASSERT_EQ(q.cells.size(), 1u);
  const CellShape& box = q.cells[0];
  EXPECT_NEAR(box.circumradius, std::sqrt(6.0) / 2, 1e-14);
  EXPECT_NEAR(box.inradius, 0.5, 1e-14);
  EXPECT_NEAR(box.aspect_ratio, std::sqrt(6.0), 1e-13);
  EXPECT_NEAR((box.circumcentre - Point(0.5, 0.5, 1)).norm(), 0, 1e-14);
  EXPECT_NEAR(box.incentre.x(), 0.5, 1e-14);  // the ball may sit anywhere along z
  EXPECT_NEAR(box.incentre.y(), 0.5, 1e-14);
  EXPECT_EQ(box.faces, 6u);
  EXPECT_EQ(box.volume, 2);
  EXPECT_NEAR(box.shortest_edge, 1, 1e-15);
  EXPECT_NEAR(box.shortest_edge_relative, 1 / std::cbrt(2.0), 1e-15);
  EXPECT_EQ(q.worst_seed, 7u);

  // The regular tetrahedron: R = 3 r.
  q = measure_cell_quality(tetrahedron_mesh());
  EXPECT_NEAR(q.cells[0].circumradius, std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(q.cells[0].inradius, 1 / std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(q.max_aspect_ratio, 3, 1e-13);
  EXPECT_NEAR(q.cells[0].incentre.norm(), 0, 1e-14);
  EXPECT_NEAR(q.cells[0].shortest_edge_relative, 2 * std::sqrt(2.0) / std::cbrt(8.0 / 3), 1e-14);

  // Orientation of the polygons does not matter: the same box with every face reversed.
  VoronoiMesh reversed = box_mesh(1, 1, 2);
  for (VoronoiFace& f : reversed.faces) std::reverse(f.points.begin(), f.points.end());
  EXPECT_NEAR(measure_cell_quality(reversed).max_aspect_ratio, std::sqrt(6.0), 1e-13);
}

// Seeds far enough inside the lattice that their cells are whole lattice cells.
std::function<std::int32_t(const Point&)> core(double lo, double hi) {
  return [=](const Point& p) { return (p.array() >= lo).all() && (p.array() <= hi).all() ? 1 : 0; };
}

TEST(CellQuality, PartsOfABox) {
  // One cell with every face to no cell: the boundary layer. Size cbrt(2); edges 1 (eight) and 2
  // (four), faces 1 x 1 (two) and 1 x 2 (four), twelve right angles.
  const CellQuality q = measure_cell_quality(box_mesh(1, 1, 2));
  const double size = std::cbrt(2.0);
  EXPECT_EQ(q.interior.cells, 0u);
  EXPECT_EQ(q.interior.edge_length.count, 0u);
  EXPECT_EQ(q.interior.edge_length.min, 0);
  const LayerParts& layer = q.boundary_layer;
  EXPECT_EQ(layer.cells, 1u);
  EXPECT_EQ(layer.edge_length.count, 12u);
  EXPECT_NEAR(layer.edge_length.min, 1 / size, 1e-15);
  EXPECT_NEAR(layer.edge_length.max, 2 / size, 1e-15);
  EXPECT_NEAR(layer.edge_length.mean, (8 + 4 * 2) / 12.0 / size, 1e-15);
  EXPECT_EQ(layer.edge_length.above_high, 0u);
  EXPECT_EQ(layer.edge_length.histogram[static_cast<std::size_t>(20 / size)], 8u);  // bins 0.05 wide
  EXPECT_EQ(layer.edge_length.histogram[static_cast<std::size_t>(40 / size)], 4u);
  EXPECT_EQ(layer.edge_length.below, (std::vector<std::size_t>{0, 0, 0}));
  EXPECT_EQ(layer.face_area.count, 6u);
  EXPECT_NEAR(layer.face_area.min, 1 / (size * size), 1e-15);
  EXPECT_EQ(layer.face_area.above_high, 0u);
  EXPECT_EQ(layer.face_area.histogram[static_cast<std::size_t>(40 / size / size)], 4u);
  EXPECT_EQ(layer.dihedral_angle.count, 12u);
  EXPECT_NEAR(layer.dihedral_angle.min, 90, 1e-12);
  EXPECT_NEAR(layer.dihedral_angle.max, 90, 1e-12);
  EXPECT_EQ(layer.dihedral_angle.histogram[9], 12u);  // [90, 100)
  EXPECT_EQ(layer.dihedral_angle.percent_below(0), 0);
}

TEST(CellQuality, PartsOfTruncatedOctahedra) {
  // The BCC lattice's cell, of edge e = sqrt(2)/4 and volume 1/2: 36 equal edges, 8 hexagons of
  // area 3 sqrt(3)/2 e^2 and 6 squares of e^2, dihedral angles acos(-1/3) at the 12 edges between
  // hexagons and acos(-1/sqrt(3)) at the 24 between a hexagon and a square. Only the core's
  // outermost cells have a face to no cell.
  const auto seeds = test::bcc_seeds(6, core(1.25, 3.75));
  const VoronoiMesh mesh = compute_cells(seeds);
  const CellQuality q = measure_cell_quality(mesh);
  const double size = std::cbrt(0.5), e = std::sqrt(2.0) / 4;
  ASSERT_GT(q.interior.cells, 0u);
  ASSERT_GT(q.boundary_layer.cells, 0u);
  EXPECT_EQ(q.interior.cells + q.boundary_layer.cells, mesh.cells.size());
  for (const LayerParts* layer : {&q.interior, &q.boundary_layer}) {
    const std::size_t n = layer->cells;
    EXPECT_EQ(layer->edge_length.count, 36 * n);
    EXPECT_NEAR(layer->edge_length.min, e / size, 1e-12);
    EXPECT_NEAR(layer->edge_length.max, e / size, 1e-12);
    EXPECT_EQ(layer->face_area.count, 14 * n);
    EXPECT_NEAR(layer->face_area.min, e * e / (size * size), 1e-12);
    EXPECT_NEAR(layer->face_area.max, 3 * std::sqrt(3.0) / 2 * e * e / (size * size), 1e-12);
    EXPECT_EQ(layer->dihedral_angle.count, 36 * n);
    EXPECT_NEAR(layer->dihedral_angle.min, std::acos(-1.0 / 3) * 180 / M_PI, 1e-9);
    EXPECT_NEAR(layer->dihedral_angle.max, std::acos(-1 / std::sqrt(3.0)) * 180 / M_PI, 1e-9);
    EXPECT_EQ(layer->dihedral_angle.histogram[10], 12 * n);  // 109.47 in [100, 110)
    EXPECT_EQ(layer->dihedral_angle.histogram[12], 24 * n);  // 125.26 in [120, 130)
  }
}

// Every cell's edges counted by hand: each edge once per cell, against that cell's size, in the
// layer its faces say (the seeds being interior ones). Two materials, so the cells along their
// interface are boundary layer too.
TEST(CellQuality, PartsAgreeWithACountByHand) {
  const auto seeds = test::lattice_seeds(9, 0.45, test::split_box_region(0.5, 7.5, 4), 5);
  const VoronoiMesh mesh = compute_cells(seeds);
  const CellQuality q = measure_cell_quality(mesh);
  std::size_t layer_cells = 0, layer_edges = 0, layer_short = 0, interior_edges = 0, interior_short = 0,
              interface_cells = 0;
  double shortest = std::numeric_limits<double>::infinity();
  std::size_t shortest_cell = 0;
  std::set<Index> interior_seeds;
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    const VoronoiCell& cell = mesh.cells[c];
    bool on_surface = false, on_interface = false;
    std::set<std::pair<Index, Index>> edges;
    for (Index f : cell.faces) {
      const VoronoiFace& face = mesh.faces[f];
      const std::int32_t other = face.owner == static_cast<std::int32_t>(c) ? face.neighbour : face.owner;
      on_interface |= other != kNoCell && mesh.cells[other].region != cell.region;
      on_surface |= other == kNoCell || mesh.cells[other].region != cell.region;
      for (std::size_t k = 0; k < face.points.size(); ++k) {
        const Index a = face.points[k], b = face.points[(k + 1) % face.points.size()];
        edges.insert({std::min(a, b), std::max(a, b)});
      }
    }
    interface_cells += on_interface;
    layer_cells += on_surface;
    if (!on_surface) interior_seeds.insert(cell.seed);
    for (const auto& [a, b] : edges) {
      const double relative = (mesh.points[a] - mesh.points[b]).norm() / std::cbrt(cell.volume);
      (on_surface ? layer_edges : interior_edges) += 1;
      (on_surface ? layer_short : interior_short) += relative < 0.1;
      if (relative < shortest) shortest = relative, shortest_cell = c;
    }
  }
  ASSERT_GT(interface_cells, 20u);
  EXPECT_EQ(q.boundary_layer.cells, layer_cells);
  EXPECT_EQ(q.boundary_layer.edge_length.count, layer_edges);
  EXPECT_EQ(q.interior.edge_length.count, interior_edges);
  EXPECT_EQ(q.boundary_layer.edge_length.below[2], layer_short);
  EXPECT_EQ(q.interior.edge_length.below[2], interior_short);
  ASSERT_GT(layer_short + interior_short, 0u);  // a jitter of 0.45 makes short edges
  const PartDistribution& holder =
      q.boundary_layer.edge_length.min < q.interior.edge_length.min ? q.boundary_layer.edge_length : q.interior.edge_length;
  EXPECT_EQ(holder.min, shortest);
  EXPECT_EQ(holder.min_cell, shortest_cell);
  // Cells of seeds on protecting spheres are boundary layer wherever they lie.
  auto capped = seeds;
  std::size_t deep_caps = 0;
  for (Index i = 0; i < capped.size(); ++i) {
    if (std::abs(capped[i].position.x() - 2) > 0.5) continue;
    capped[i].kind = SeedKind::Cap;
    deep_caps += interior_seeds.count(i);
  }
  const CellQuality with_caps = measure_cell_quality(compute_cells(capped));
  ASSERT_GT(deep_caps, 5u);
  EXPECT_EQ(with_caps.boundary_layer.cells, layer_cells + deep_caps);
  EXPECT_EQ(with_caps.interior.cells, q.interior.cells - deep_caps);
  for (const LayerParts* layer : {&q.interior, &q.boundary_layer}) {
    const PartDistribution& d = layer->dihedral_angle;
    EXPECT_EQ(std::accumulate(d.histogram.begin(), d.histogram.end(), d.above_high), d.count);
    EXPECT_GT(d.min, 0);
    EXPECT_LT(d.max, 180);  // convex cells
  }
}

struct LatticeCase {
  const char* name;
  std::vector<Seed> seeds;
  double aspect_ratio, volume, shortest_edge;
  std::size_t faces;
};

TEST(CellQuality, LatticeCellsHaveTheirExactFigures) {
  const std::vector<LatticeCase> cases = {
      // The cube: R = sqrt(3)/2, r = 1/2.
      {"cubic", test::lattice_seeds(7, 0, core(1.5, 4.5)), std::sqrt(3.0), 1, 1, 6},
      // The truncated octahedron of edge e = sqrt(2)/4: R = e sqrt(10)/2, r = e sqrt(6)/2 (to
      // the hexagons); volume 1/2, two seeds a unit cube.
      {"bcc", test::bcc_seeds(6, core(1.25, 3.75)), std::sqrt(5.0 / 3), 0.5, std::sqrt(2.0) / 4, 14},
      // The rhombic dodecahedron: R = 1/2 (to its six 4-valent corners), r = sqrt(2)/4, edge
      // sqrt(3)/4; volume 1/4.
      {"fcc", test::fcc_seeds(6, core(1.25, 3.75)), std::sqrt(2.0), 0.25, std::sqrt(3.0) / 4, 12},
  };
  for (const LatticeCase& lattice : cases) {
    SCOPED_TRACE(lattice.name);
    const VoronoiMesh mesh = compute_cells(lattice.seeds);
    ASSERT_GT(mesh.cells.size(), 20u);
    const CellQuality q = measure_cell_quality(mesh);
    ASSERT_EQ(q.cells.size(), mesh.cells.size());
    for (std::size_t c = 0; c < q.cells.size(); ++c) {
      const CellShape& s = q.cells[c];
      const Point& seed = lattice.seeds[mesh.cells[c].seed].position;
      ASSERT_NEAR(s.aspect_ratio, lattice.aspect_ratio, 1e-9) << "cell " << c;
      ASSERT_EQ(s.faces, lattice.faces) << "cell " << c;
      ASSERT_NEAR(s.volume, lattice.volume, 1e-9);
      ASSERT_NEAR(s.shortest_edge, lattice.shortest_edge, 1e-9);
      ASSERT_NEAR(s.shortest_edge_relative, lattice.shortest_edge / std::cbrt(lattice.volume), 1e-9);
      // Both spheres are centred on the seed, the cell's centre of symmetry.
      ASSERT_LT((s.circumcentre - seed).norm(), 1e-9);
      ASSERT_LT((s.incentre - seed).norm(), 1e-9);
    }
    EXPECT_NEAR(q.min_aspect_ratio, lattice.aspect_ratio, 1e-9);
    EXPECT_NEAR(q.max_aspect_ratio, lattice.aspect_ratio, 1e-9);
    EXPECT_NEAR(q.mean_aspect_ratio, lattice.aspect_ratio, 1e-9);
    EXPECT_EQ(q.min_faces, lattice.faces);
    EXPECT_EQ(q.max_faces, lattice.faces);
    EXPECT_EQ(q.mean_faces, static_cast<double>(lattice.faces));
    EXPECT_NEAR(q.total_volume, lattice.volume * static_cast<double>(mesh.cells.size()), 1e-8);
    // Every cell in the bin of its ratio: [1 + k/4, 1 + (k+1)/4) with the default 16 bins to 5.
    ASSERT_EQ(q.aspect_ratio_histogram.size(), 16u);
    const auto bin = static_cast<std::size_t>((lattice.aspect_ratio - 1) * 4);
    EXPECT_EQ(q.aspect_ratio_histogram[bin], mesh.cells.size());
    EXPECT_EQ(q.aspect_ratio_above_high, 0u);
  }
}

TEST(CellQuality, JitteredCellsKeepTheirSpheresAndAddUp) {
  const auto seeds = test::lattice_seeds(12, 0.3, test::ball_region(Point(5.5, 5.5, 5.5), 4.2), 4);
  const VoronoiMesh mesh = compute_cells(seeds);
  CellQualityOptions options;
  options.histogram_bins = 10;
  options.histogram_high = 3;
  const CellQuality q = measure_cell_quality(mesh, options);
  ASSERT_EQ(q.cells.size(), mesh.cells.size());
  double ratio_sum = 0, volume_sum = 0;
  std::size_t worst = 0;
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    const CellShape& s = q.cells[c];
    const VoronoiCell& cell = mesh.cells[c];
    double diameter = 0, farthest = 0, shortest = std::numeric_limits<double>::infinity();
    for (Index f : cell.faces) {
      const auto& polygon = mesh.faces[f].points;
      for (std::size_t k = 0; k < polygon.size(); ++k) {
        const Point& p = mesh.points[polygon[k]];
        farthest = std::max(farthest, (p - s.circumcentre).norm());
        shortest = std::min(shortest, (p - mesh.points[polygon[(k + 1) % polygon.size()]]).norm());
        for (Index g : cell.faces)
          for (Index o : mesh.faces[g].points) diameter = std::max(diameter, (p - mesh.points[o]).norm());
      }
    }
    EXPECT_LE(farthest, s.circumradius * (1 + 1e-12)) << "encloses, cell " << c;
    EXPECT_GE(s.circumradius, diameter / 2 * (1 - 1e-12)) << "no smaller than half the diameter, cell " << c;
    EXPECT_LE(s.circumradius, diameter * std::sqrt(3.0 / 8) * (1 + 1e-12)) << "Jung's bound, cell " << c;
    // The largest ball inside is no smaller than the ball about the seed to its nearest face,
    // half the distance to the nearest seed across a face; and its volume fits.
    double nearest = std::numeric_limits<double>::infinity();
    for (Index f : cell.faces) {
      const VoronoiFace& face = mesh.faces[f];
      nearest = std::min(nearest, (seeds[face.owner_seed].position - seeds[face.neighbour_seed].position).norm() / 2);
    }
    EXPECT_GE(s.inradius, nearest * (1 - 1e-9)) << "cell " << c;
    EXPECT_LE(4.0 / 3 * M_PI * std::pow(s.inradius, 3), s.volume);
    EXPECT_GE(s.aspect_ratio, 1);
    EXPECT_NEAR(s.aspect_ratio, s.circumradius / s.inradius, 1e-15 * s.aspect_ratio);
    EXPECT_EQ(s.shortest_edge, shortest);
    EXPECT_EQ(s.faces, cell.faces.size());
    ratio_sum += s.aspect_ratio;
    volume_sum += s.volume;
    if (s.aspect_ratio > q.cells[worst].aspect_ratio) worst = c;
  }
  EXPECT_EQ(q.worst_cell, worst);
  EXPECT_EQ(q.worst_seed, mesh.cells[worst].seed);
  EXPECT_EQ(q.max_aspect_ratio, q.cells[worst].aspect_ratio);
  EXPECT_EQ(q.total_volume, volume_sum);
  EXPECT_NEAR(q.mean_aspect_ratio, ratio_sum / static_cast<double>(q.cells.size()), 1e-12);
  ASSERT_EQ(q.aspect_ratio_histogram.size(), 10u);
  EXPECT_EQ(q.histogram_high, 3);
  const std::size_t binned = std::accumulate(q.aspect_ratio_histogram.begin(), q.aspect_ratio_histogram.end(),
                                             std::size_t{0});
  EXPECT_EQ(binned + q.aspect_ratio_above_high, q.cells.size());
  std::size_t above = 0;
  for (const CellShape& s : q.cells) above += s.aspect_ratio > 3;
  EXPECT_EQ(q.aspect_ratio_above_high, above);
  EXPECT_GT(q.max_aspect_ratio, q.min_aspect_ratio);
}

// Each face plane has the inscribed ball on its inner side: the ball fits the cell.
TEST(CellQuality, InscribedBallFitsEveryFace) {
  const auto seeds = test::lattice_seeds(10, 0.45, test::ball_region(Point(4.5, 4.5, 4.5), 3.5), 9);
  const VoronoiMesh mesh = compute_cells(seeds);
  const CellQuality q = measure_cell_quality(mesh);
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    const CellShape& s = q.cells[c];
    // The seed is inside its Voronoi cell; every face is on the bisector of its two seeds, so
    // the distance from a point to the face plane is measured along the seed link.
    for (Index f : mesh.cells[c].faces) {
      const VoronoiFace& face = mesh.faces[f];
      const Point own = seeds[mesh.cells[c].seed].position;
      const Point other = seeds[face.owner_seed == mesh.cells[c].seed ? face.neighbour_seed : face.owner_seed].position;
      const Point n = (other - own).normalized();
      const double offset = n.dot(own + other) / 2;
      EXPECT_LE(n.dot(s.incentre) + s.inradius, offset + 1e-9) << "cell " << c << " face " << f;
    }
  }
}

// Cell c of `mesh` against brute force over its points and over the bisector planes of its seed
// links (the cell as the Voronoi diagram defines it, not as its polygons give it); the enclosing
// sphere only up to `max_points` points, brute force being slow.
void expect_brute_force_spheres(const VoronoiMesh& mesh, const std::vector<Seed>& seeds, const CellQuality& q,
                                std::size_t c, std::size_t max_points = 64) {
  const CellShape& s = q.cells[c];
  std::vector<Point> points;
  std::vector<geometry::Plane> planes;
  for (Index f : mesh.cells[c].faces) {
    const VoronoiFace& face = mesh.faces[f];
    for (Index p : face.points) points.push_back(mesh.points[p]);
    const Point a = seeds[face.owner_seed].position, b = seeds[face.neighbour_seed].position;
    const Point outward = (face.owner_seed == mesh.cells[c].seed ? b - a : a - b).normalized();
    planes.push_back({outward, outward.dot(a + b) / 2});
  }
  std::sort(points.begin(), points.end(), [](const Point& x, const Point& y) {
    return std::tie(x.x(), x.y(), x.z()) < std::tie(y.x(), y.y(), y.z());
  });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() <= max_points) {
    EXPECT_NEAR(s.circumradius, geometry::brute_force_enclosing_radius(points), 1e-9 * s.circumradius) << "cell " << c;
  }
  EXPECT_NEAR(s.inradius, geometry::brute_force_inscribed_radius(planes), 1e-9 * s.circumradius) << "cell " << c;
}

// Cells of a lattice moved by a thousandth or less: tiny faces and edges next to large ones,
// points nearly cospherical.
TEST(CellQuality, NearDegenerateCellsAgreeWithBruteForce) {
  for (double jitter : {1e-3, 1e-5}) {
    SCOPED_TRACE(jitter);
    const auto seeds = test::lattice_seeds(6, jitter, test::ball_region(Point(2.5, 2.5, 2.5), 1.8), 13);
    const VoronoiMesh mesh = compute_cells(seeds);
    ASSERT_GE(mesh.cells.size(), 8u);
    const CellQuality q = measure_cell_quality(mesh);
    for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
      expect_brute_force_spheres(mesh, seeds, q, c);
      EXPECT_NEAR(q.cells[c].aspect_ratio, std::sqrt(3.0), 0.01) << "cell " << c;
    }
  }
}

// The cells of a real VoroCrust seed set, the surface seeds of cgal_joint.off: many seeds on one
// sphere about every ball centre, long thin cells across the surface.
TEST(CellQuality, SurfaceSeedCellsAgreeWithBruteForce) {
  MeshOptions options;
  options.stop_after = Stage::Surface;
  const MeshResult r = generate_mesh(read_mesh(test::model("cgal_joint.off")), options);
  const VoronoiMesh mesh = compute_cells(r.seeds);
  const CellQuality q = measure_cell_quality(mesh);
  ASSERT_GT(mesh.cells.size(), 5000u);
  for (std::size_t c = 0; c < mesh.cells.size(); c += 37) expect_brute_force_spheres(mesh, r.seeds, q, c, 30);
  EXPECT_TRUE(std::isfinite(q.max_aspect_ratio));
  EXPECT_GT(q.max_aspect_ratio, q.mean_aspect_ratio);
  EXPECT_GT(q.mean_aspect_ratio, q.min_aspect_ratio);
}

TEST(CellQuality, SameFiguresForOneAndTwoThreads) {
  const auto seeds = test::lattice_seeds(16, 0.35, test::ball_region(Point(7.5, 7.5, 7.5), 7), 2);
  const VoronoiMesh mesh = compute_cells(seeds);
  CellQualityOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const CellQuality a = measure_cell_quality(mesh, one), b = measure_cell_quality(mesh, two);
  ASSERT_EQ(a.cells.size(), b.cells.size());
  for (std::size_t c = 0; c < a.cells.size(); ++c) {
    ASSERT_EQ(a.cells[c].aspect_ratio, b.cells[c].aspect_ratio);
    ASSERT_EQ(a.cells[c].incentre, b.cells[c].incentre);
    ASSERT_EQ(a.cells[c].circumcentre, b.cells[c].circumcentre);
  }
  EXPECT_EQ(a.mean_aspect_ratio, b.mean_aspect_ratio);
  EXPECT_EQ(a.total_volume, b.total_volume);
  EXPECT_EQ(a.aspect_ratio_histogram, b.aspect_ratio_histogram);
  for (auto layer : {&CellQuality::boundary_layer, &CellQuality::interior}) {
    for (auto part : {&LayerParts::edge_length, &LayerParts::face_area, &LayerParts::dihedral_angle}) {
      EXPECT_EQ((a.*layer.*part).mean, (b.*layer.*part).mean);
      EXPECT_EQ((a.*layer.*part).histogram, (b.*layer.*part).histogram);
      EXPECT_EQ((a.*layer.*part).min_cell, (b.*layer.*part).min_cell);
    }
  }
}

void expect_error(const VoronoiMesh& mesh, const CellQualityOptions& options, Error::Kind kind,
                  const std::string& phrase) {
  try {
    measure_cell_quality(mesh, options);
    FAIL() << "no error for " << phrase;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), kind);
    EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
  }
}

TEST(CellQuality, BadInputAndOptions) {
  expect_error({}, {}, Error::Kind::InvalidGeometry, "the mesh has no cells");
  VoronoiMesh missing_face = box_mesh(1, 1, 1);
  missing_face.cells[0].faces.push_back(9);
  expect_error(missing_face, {}, Error::Kind::InvalidGeometry, "cell 0 names face 9 of 6");
  VoronoiMesh missing_point = box_mesh(1, 1, 1);
  missing_point.faces[2].points[1] = 8;
  expect_error(missing_point, {}, Error::Kind::InvalidGeometry, "cell 0 has point 8 of 8");
  CellQualityOptions bins;
  bins.histogram_bins = 0;
  expect_error(box_mesh(1, 1, 1), bins, Error::Kind::Usage, "1 to 1000 bins, got 0");
  CellQualityOptions high;
  high.histogram_high = 1;
  expect_error(box_mesh(1, 1, 1), high, Error::Kind::Usage, "must end above 1");
  high.histogram_high = std::numeric_limits<double>::infinity();
  expect_error(box_mesh(1, 1, 1), high, Error::Kind::Usage, "must end above 1");
  CellQualityOptions threads;
  threads.threads = -1;
  expect_error(box_mesh(1, 1, 1), threads, Error::Kind::Usage, "threads");
}

TEST(CellQuality, FlatCellHasInfiniteAspectRatio) {
  // A box of no height: no interior, counted above the histogram.
  const CellQuality q = measure_cell_quality(box_mesh(1, 1, 0));
  EXPECT_EQ(q.cells[0].inradius, 0);
  EXPECT_TRUE(std::isinf(q.max_aspect_ratio));
  EXPECT_EQ(q.aspect_ratio_above_high, 1u);
}

}  // namespace
}  // namespace vorocrust
