// Patch smoothing (adaptive Loop subdivision): sharp features stay exactly, patches get flatter,
// the topology and every non-manifold or boundary edge survive, the mesh stays conforming.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <set>

#include "core/edge_topology.hpp"
#include "core/surface_measures.hpp"
#include "features/smooth_patches.hpp"
#include "features/strata.hpp"
#include "test_support.hpp"
#include "vorocrust/mesher.hpp"
#include "vorocrust/quality.hpp"
#include "vorocrust/read_mesh.hpp"
#include "vorocrust/validate.hpp"

namespace vorocrust {
namespace {


struct Smoothing {
  SurfaceMesh input;
  Strata strata;
  SmoothedSurface out;
  double seconds = 0;
};

Smoothing smooth_model(const std::string& model, const SmoothingOptions& options = {}, double sharp_degrees = 30) {
  Smoothing run;
  run.input = read_mesh(test::model(model));
  (void)validate(run.input);
  run.strata = detect_strata(run.input, sharp_degrees * test::kDegree);
  const auto start = std::chrono::steady_clock::now();
  run.out = smooth_patches(run.input, run.strata, options);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

// How far patches are from flat: angles (degrees) between the normals across non-sharp edges.
struct Bend {
  double max = 0, mean = 0, p99 = 0;
  std::size_t above_5 = 0, edges = 0;
  double fraction_above_5() const { return edges > 0 ? static_cast<double>(above_5) / static_cast<double>(edges) : 0; }
};

Bend patch_bend(const SurfaceMesh& mesh, const Strata& s) {
  Bend bend;
  double sum = 0;
  std::vector<double> angles;
  for (std::size_t e = 0; e < s.topology.num_edges(); ++e) {
    if (s.sharp_edge[e]) continue;
    const auto faces = s.topology.faces_of(e);
    const double angle =
        std::acos(std::clamp(face_normal(mesh, faces[0]).dot(face_normal(mesh, faces[1])), -1.0, 1.0)) / test::kDegree;
    bend.max = std::max(bend.max, angle);
    angles.push_back(angle);
    sum += angle;
    bend.above_5 += angle > 5.0 + 1e-9;
    ++bend.edges;
  }
  bend.mean = bend.edges > 0 ? sum / static_cast<double>(bend.edges) : 0;
  if (!angles.empty()) {
    std::nth_element(angles.begin(), angles.begin() + angles.size() * 99 / 100, angles.end());
    bend.p99 = angles[angles.size() * 99 / 100];
  }
  return bend;
}

double min_angle_degrees(const SurfaceMesh& mesh) {
  double least = 180;
  for (const Triangle& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Point u = mesh.vertices[t[(k + 1) % 3]] - mesh.vertices[t[k]];
      const Point v = mesh.vertices[t[(k + 2) % 3]] - mesh.vertices[t[k]];
      least = std::min(least, std::atan2(u.cross(v).norm(), u.dot(v)) / test::kDegree);
    }
  }
  return least;
}

double enclosed_volume(const SurfaceMesh& mesh) {
  double six_v = 0;
  for (const Triangle& t : mesh.triangles) {
    six_v += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]]));
  }
  return six_v / 6;
}

// Euler characteristic V - E + F of each face-connected component (sorted), and edge counts.
struct Topology {
  std::vector<long> euler;
  std::size_t boundary = 0, non_manifold = 0, misoriented = 0;
};

Topology topology_of(const SurfaceMesh& mesh) {
  const EdgeTopology topo = build_edge_topology(mesh);
  std::size_t count = 0;
  const std::vector<Index> component = label_face_components(mesh, topo, [](std::size_t) { return true; }, count);
  std::vector<long> chi(count, 0);
  std::set<std::pair<Index, Index>> used;  // (component, vertex)
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    ++chi[component[f]];
    for (Index v : mesh.triangles[f]) {
      if (used.insert({component[f], v}).second) ++chi[component[f]];
    }
  }
  Topology t;
  for (std::size_t e = 0; e < topo.num_edges(); ++e) {
    const auto faces = topo.faces_of(e);
    --chi[component[faces[0]]];
    t.boundary += topo.is_boundary(e);
    t.non_manifold += topo.is_non_manifold(e);
    if (faces.size() == 2) {
      const auto [a, b] = topo.edges[e];
      t.misoriented += edge_direction(mesh.triangles[faces[0]], a, b) == edge_direction(mesh.triangles[faces[1]], a, b);
    }
  }
  std::sort(chi.begin(), chi.end());
  t.euler = std::move(chi);
  return t;
}

std::size_t edge_index(const EdgeTopology& topo, Index a, Index b) {
  const std::array<Index, 2> key{std::min(a, b), std::max(a, b)};
  const auto it = std::lower_bound(topo.edges.begin(), topo.edges.end(), key);
  return it != topo.edges.end() && *it == key ? static_cast<std::size_t>(it - topo.edges.begin()) : SIZE_MAX;
}

// Everything smoothing promises, whatever the model. Walks each input sharp edge from one end to
// the other through the output's sharp edges, which must run along it through new vertices only.
void expect_invariants(const Smoothing& run) {
  const SurfaceMesh& in = run.input;
  const SurfaceMesh& out = run.out.mesh;
  const Strata& s = run.strata;
  const EdgeTopology out_topo = build_edge_topology(out);
  const std::size_t v_in = in.num_vertices();
  ASSERT_GE(out.num_vertices(), v_in);
  ASSERT_EQ(out.triangles.size(), out.face_group.size());
  ASSERT_EQ(out.triangles.size(), out.face_line.size());
  ASSERT_EQ(out.has_regions(), in.has_regions());
  if (out.has_regions()) { ASSERT_EQ(out.face_regions.size(), out.triangles.size()); }
  // Each child is named in messages as its parent is (by the face as read that the parent came
  // from, and its line); every face has a child.
  ASSERT_TRUE(out.face_source.empty() || out.face_source.size() == out.triangles.size());
  std::map<Index, std::string> named;
  for (std::size_t p = 0; p < in.num_faces(); ++p) named[in.source_face(p)] = describe_face(in, p);
  std::set<Index> with_child;
  for (std::size_t f = 0; f < out.num_faces(); ++f) {
    const auto it = named.find(out.source_face(f));
    ASSERT_NE(it, named.end()) << f;
    EXPECT_EQ(describe_face(out, f), it->second) << f;
    with_child.insert(it->first);
  }
  EXPECT_EQ(with_child.size(), named.size()) << "faces with no child";

  EXPECT_EQ(run.out.corners, s.corners);
  for (Index c : s.corners) EXPECT_EQ(out.vertices[c], in.vertices[c]) << "corner " << c << " moved";

  // Output sharp edges by vertex.
  std::multimap<Index, std::size_t> sharp_at;
  for (std::size_t i = 0; i < run.out.sharp_edges.size(); ++i) {
    const auto [a, b] = run.out.sharp_edges[i];
    ASSERT_LT(a, b);
    sharp_at.insert({a, i});
    sharp_at.insert({b, i});
  }
  std::vector<bool> used(run.out.sharp_edges.size(), false);
  double length_in = 0, length_out = 0;
  std::size_t expected_boundary = 0, expected_non_manifold = 0;
  for (std::size_t e = 0; e < s.topology.num_edges(); ++e) {
    if (!s.sharp_edge[e]) continue;
    const auto [a, b] = s.topology.edges[e];
    EXPECT_EQ(out.vertices[a], in.vertices[a]) << "crease vertex " << a << " moved";
    EXPECT_EQ(out.vertices[b], in.vertices[b]) << "crease vertex " << b << " moved";
    const Point pa = in.vertices[a], pb = in.vertices[b];
    const double len = (pb - pa).norm();
    length_in += len;
    Index cur = a;
    double t_cur = 0;
    std::size_t pieces = 0;
    while (cur != b) {
      bool found = false;
      for (auto [it, end] = sharp_at.equal_range(cur); it != end; ++it) {
        if (used[it->second]) continue;
        const auto [u, w0] = run.out.sharp_edges[it->second];
        const Index w = u == cur ? w0 : u;
        const Point pw = out.vertices[w];
        const double t = (pw - pa).dot(pb - pa) / (len * len);
        const double off_line = ((pw - pa) - t * (pb - pa)).norm();
        if (w != b && !(w >= v_in && t > t_cur && t < 1 && off_line <= 1e-12 * len)) continue;
        used[it->second] = true;
        length_out += (pw - out.vertices[cur]).norm();
        const std::size_t oe = edge_index(out_topo, cur, w);
        EXPECT_NE(oe, SIZE_MAX);
        if (oe != SIZE_MAX) { EXPECT_EQ(out_topo.valence(oe), s.topology.valence(e)); }
        cur = w;
        t_cur = t;
        ++pieces;
        found = true;
        break;
      }
      ASSERT_TRUE(found) << "input sharp edge " << a << "-" << b << " is not covered by output sharp edges";
    }
    if (s.topology.is_boundary(e)) expected_boundary += pieces;
    if (s.topology.is_non_manifold(e)) expected_non_manifold += pieces;
  }
  EXPECT_TRUE(std::all_of(used.begin(), used.end(), [](bool u) { return u; }))
      << "an output sharp edge lies on no input sharp edge";
  EXPECT_NEAR(length_out, length_in, 1e-12 * length_in);  // creases keep their exact length

  // Conforming, same topology: components and their Euler characteristics, and boundary and
  // non-manifold edges only where the input had them (a T-junction would add boundary edges).
  const Topology before = topology_of(in), after = topology_of(out);
  EXPECT_EQ(after.euler, before.euler);
  EXPECT_EQ(after.boundary, expected_boundary);
  EXPECT_EQ(after.non_manifold, expected_non_manifold);
  EXPECT_LE(after.misoriented, before.misoriented);
  if (before.misoriented == 0) { EXPECT_EQ(after.misoriented, 0u); }

  // No face introduced with zero area, and no source face lost.
  for (std::size_t f = 0; f < out.num_faces(); ++f) {
    const Triangle& t = out.triangles[f];
    const double area2 = (out.vertices[t[1]] - out.vertices[t[0]]).cross(out.vertices[t[2]] - out.vertices[t[0]]).norm();
    EXPECT_GT(area2, 0) << "degenerate face " << f;
  }
  std::set<std::pair<Index, std::uint32_t>> sources_in, sources_out;
  for (std::size_t f = 0; f < in.num_faces(); ++f) sources_in.insert({in.face_group[f], in.face_line[f]});
  for (std::size_t f = 0; f < out.num_faces(); ++f) sources_out.insert({out.face_group[f], out.face_line[f]});
  EXPECT_EQ(sources_out, sources_in);

  // The strata carried through are consistent and as many as before, and no patch edge ends up
  // bent more than the worst one of the input (the kink guard's promise).
  const Strata after_strata = strata_after_smoothing(run.out);
  EXPECT_LE(patch_bend(out, after_strata).max, std::max(patch_bend(in, s).max, 5.0) + 1e-6);
  EXPECT_EQ(after_strata.corners, s.corners);
  EXPECT_EQ(after_strata.creases.size(), s.creases.size());
  EXPECT_EQ(after_strata.num_patches, s.num_patches);
}

void print(const char* model, const Smoothing& run) {
  const Strata after = strata_after_smoothing(run.out);
  const Bend b0 = patch_bend(run.input, run.strata), b1 = patch_bend(run.out.mesh, after);
  std::printf(
      "[smooth] %-28s faces %7zu -> %8zu  rounds %d  split %8zu  bend (deg) max %6.2f -> %6.2f, p99 %5.2f -> %5.2f, "
      "mean %5.2f -> %5.2f, edges >5deg %5.1f%% -> %5.1f%%  min angle %5.2f -> %5.2f  %.3f s\n",
      model, run.input.num_faces(), run.out.mesh.num_faces(), run.out.iterations, run.out.faces_split, b0.max, b1.max,
      b0.p99, b1.p99, b0.mean, b1.mean, 100 * b0.fraction_above_5(), 100 * b1.fraction_above_5(),
      min_angle_degrees(run.input), min_angle_degrees(run.out.mesh), run.seconds);
}

// ---- Small shapes with known answers ----

SurfaceMesh icosahedron() {
  SurfaceMesh mesh;
  const double g = (1 + std::sqrt(5.0)) / 2;
  const double pts[12][3] = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                             {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  for (const auto& p : pts) mesh.vertices.push_back(Point(p[0], p[1], p[2]).normalized());
  const Triangle faces[20] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                              {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                              {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  mesh.groups.push_back({"ico", ""});
  for (std::uint32_t f = 0; f < 20; ++f) mesh.add_triangle(faces[f], 0, f + 1);
  return mesh;
}

// A flat n x n grid of squares (two triangles each) in z = 0 with its centre vertex raised.
SurfaceMesh bumped_grid(int n, double height) {
  SurfaceMesh mesh;
  mesh.groups.push_back({"grid", ""});
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) mesh.vertices.emplace_back(i, j, (i == n / 2 && j == n / 2) ? height : 0.0);
  }
  const auto at = [&](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  std::uint32_t line = 1;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      mesh.add_triangle({at(i, j), at(i + 1, j), at(i + 1, j + 1)}, 0, line++);
      mesh.add_triangle({at(i, j), at(i + 1, j + 1), at(i, j + 1)}, 0, line++);
    }
  }
  return mesh;
}

Smoothing smooth_mesh(SurfaceMesh mesh, double sharp_degrees, const SmoothingOptions& options = {}) {
  Smoothing run;
  run.input = std::move(mesh);
  run.strata = detect_strata(run.input, sharp_degrees * test::kDegree);
  run.out = smooth_patches(run.input, run.strata, options);
  return run;
}

TEST(SmoothPatches, OneUniformRoundOnAnIcosahedronFollowsLoopsRules) {
  // At theta# = 80 degrees the icosahedron has no sharp edge and no corner: every face is bent
  // by 41.8 degrees, so one round splits all 20 faces red.
  const Smoothing run = smooth_mesh(icosahedron(), 80, {.max_iterations = 1});
  ASSERT_TRUE(run.strata.corners.empty());
  EXPECT_EQ(run.out.iterations, 1);
  EXPECT_EQ(run.out.faces_split, 20u);
  ASSERT_EQ(run.out.mesh.num_faces(), 80u);
  ASSERT_EQ(run.out.mesh.num_vertices(), 42u);
  // Loop's original vertex rule at valence 5; the five neighbours of a unit vertex v sum to
  // 5 v / sqrt(5) in the direction of v.
  const double c = 3.0 / 8 + std::cos(2 * std::numbers::pi / 5) / 4;
  const double beta = (5.0 / 8 - c * c) / 5;
  const double vertex_radius = 1 - 5 * beta * (1 - 1 / std::sqrt(5.0));
  for (Index v = 0; v < 12; ++v) EXPECT_NEAR(run.out.mesh.vertices[v].norm(), vertex_radius, 1e-14);
  // Edge point: 3/8 (a + b) + 1/8 (c + d) has the same length on every edge by symmetry.
  const Point edge_point = 3.0 / 8 * (run.input.vertices[0] + run.input.vertices[11]) +
                           1.0 / 8 * (run.input.vertices[5] + run.input.vertices[10]);
  for (Index v = 12; v < 42; ++v) EXPECT_NEAR(run.out.mesh.vertices[v].norm(), edge_point.norm(), 1e-14);
  expect_invariants(run);
}

TEST(SmoothPatches, IcosahedronConvergesTowardsARoundSurface) {
  const Smoothing run = smooth_mesh(icosahedron(), 80);
  expect_invariants(run);
  const Strata after = strata_after_smoothing(run.out);
  EXPECT_LT(patch_bend(run.out.mesh, after).max, 5.0 + 1e-9);
  EXPECT_LE(run.out.iterations, 6);
  EXPECT_EQ(topology_of(run.out.mesh).euler, std::vector<long>{2});
}

TEST(SmoothPatches, ABumpIsRefinedLocallyAndConformingly) {
  // Low enough that the bump's top is no cone corner at theta# = 60 degrees.
  const Smoothing run = smooth_mesh(bumped_grid(12, 0.2), 60);
  print("bumped grid 12x12", run);
  ASSERT_EQ(run.strata.corners.size(), 4u);  // the grid's own corners
  expect_invariants(run);
  EXPECT_GE(run.out.iterations, 2);
  // Far from the bump nothing moves and nothing is split: the grid's corner squares are intact.
  const SurfaceMesh& out = run.out.mesh;
  for (Index v = 0; v < run.input.num_vertices(); ++v) {
    const Point p = run.input.vertices[v];
    if (std::abs(p.x() - 6) + std::abs(p.y() - 6) >= 9) { EXPECT_EQ(out.vertices[v], p); }
  }
  for (std::size_t f : {std::size_t{0}, std::size_t{1}}) {
    EXPECT_NE(std::find(out.triangles.begin(), out.triangles.end(), run.input.triangles[f]), out.triangles.end());
  }
  // Red-green keeps shapes: no angle far below the grid's 45 degrees (green bisection of a red
  // child halves an angle at most once).
  EXPECT_GT(min_angle_degrees(out), 10.0);
  const Strata after = strata_after_smoothing(run.out);
  EXPECT_LT(patch_bend(out, after).max, patch_bend(run.input, run.strata).max);
}

TEST(SmoothPatches, AConeCornerKeepsItsCone) {
  // A steep bump: its top is a corner (normals in its one sector differ by more than theta#) with
  // no sharp edge. Its fan is split linearly, so every face at the top stays in the plane of the
  // input face it comes from.
  const Smoothing run = smooth_mesh(bumped_grid(12, 0.6), 60);
  const Index top = 6 * 13 + 6;
  ASSERT_NE(run.strata.vertex_corner[top], Strata::kNone);
  expect_invariants(run);
  EXPECT_GT(run.out.iterations, 0);
  const SurfaceMesh& out = run.out.mesh;
  std::size_t at_top = 0;
  for (std::size_t f = 0; f < out.num_faces(); ++f) {
    const Triangle& t = out.triangles[f];
    if (std::find(t.begin(), t.end(), top) == t.end()) continue;
    ++at_top;
    const Point n = face_normal(out, static_cast<Index>(f));
    double best = -1;
    for (std::size_t g = 0; g < run.input.num_faces(); ++g) {
      const Triangle& u = run.input.triangles[g];
      if (std::find(u.begin(), u.end(), top) != u.end()) best = std::max(best, n.dot(face_normal(run.input, static_cast<Index>(g))));
    }
    EXPECT_NEAR(best, 1.0, 1e-12) << "face " << f;
  }
  EXPECT_EQ(at_top, 6u);
}

TEST(SmoothPatches, BuildStrataReproducesDetection) {
  for (const char* model : {"cgal_fandisk.off", "sandia_bracket.obj", "sandia_non_manifold_box.obj",
                            "cgal_cubes_edge_contact.off", "sandia_OneBox.obj", "gmsh_terrain.stl"}) {
    SCOPED_TRACE(model);
    SurfaceMesh mesh = read_mesh(test::model(model));
    (void)validate(mesh);
    const Strata detected = detect_strata(mesh, 30 * test::kDegree);
    std::vector<bool> corner(mesh.num_vertices(), false);
    for (Index v : detected.corners) corner[v] = true;
    const Strata built = build_strata(mesh, detected.sharp_edge, corner);
    EXPECT_EQ(built.sharp_edge, detected.sharp_edge);
    EXPECT_EQ(built.corners, detected.corners);
    EXPECT_EQ(built.creases.size(), detected.creases.size());
    EXPECT_EQ(built.num_patches, detected.num_patches);
    EXPECT_EQ(built.face_patch, detected.face_patch);
    EXPECT_EQ(built.corner_creases, detected.corner_creases);
    EXPECT_EQ(built.corner_patches, detected.corner_patches);
    EXPECT_EQ(built.edge_tangent, detected.edge_tangent);
    // Same creases as edge sets (a walk around a cycle may start elsewhere).
    const auto crease_sets = [](const Strata& st) {
      std::vector<std::vector<Index>> sets;
      for (const Crease& c : st.creases) {
        sets.push_back(c.edges);
        std::sort(sets.back().begin(), sets.back().end());
      }
      std::sort(sets.begin(), sets.end());
      return sets;
    };
    EXPECT_EQ(crease_sets(built), crease_sets(detected));
  }
}

// ---- The shared models ----

TEST(SmoothPatches, BunnyGetsFlatterPatches) {
  const Smoothing run = smooth_model("igl_bunny.off");
  print("igl_bunny.off", run);
  expect_invariants(run);
  const Strata after = strata_after_smoothing(run.out);
  const Bend b0 = patch_bend(run.input, run.strata), b1 = patch_bend(run.out.mesh, after);
  // At theta# = 30 degrees the decimated bunny has about a thousand corners; the worst bend sits
  // on a cone corner's fan, which is kept (corners never move), so the maximum can only hold.
  // Everywhere else the patches flatten.
  EXPECT_LE(b1.max, b0.max + 1e-6);
  EXPECT_LT(b1.p99, 0.5 * b0.p99);
  EXPECT_LT(b1.mean, 0.5 * b0.mean);
  EXPECT_LT(b1.fraction_above_5(), 0.1 * b0.fraction_above_5());
  // Each round at most quadruples the faces (red 1->4, green 1->2, a merged green pair 2->6),
  // and max_faces caps the total.
  EXPECT_GT(run.out.mesh.num_faces(), run.input.num_faces());
  EXPECT_LE(run.out.mesh.num_faces(), run.input.num_faces() << (2 * run.out.iterations));
  EXPECT_LE(run.out.mesh.num_faces(), SmoothingOptions{}.max_faces);
}

void expect_sharp_model(const char* model) {
  const Smoothing run = smooth_model(model);
  print(model, run);
  expect_invariants(run);
  EXPECT_GT(run.out.iterations, 0);
  EXPECT_FALSE(run.strata.corners.empty());
  // The worst bends of these CAD models sit where a crease turns at a vertex that is no corner;
  // those kinks are the input's and stay (crease vertices never move), so the maximum holds.
  const Strata after = strata_after_smoothing(run.out);
  EXPECT_LE(patch_bend(run.out.mesh, after).max, patch_bend(run.input, run.strata).max + 1e-6);
}

TEST(SmoothPatches, FandiskKeepsItsCreasesExactly) { expect_sharp_model("cgal_fandisk.off"); }

TEST(SmoothPatches, BracketKeepsItsCreasesExactly) { expect_sharp_model("sandia_bracket.obj"); }

TEST(SmoothPatches, TorusShrinksOnlySlightly) {
  const Smoothing run = smooth_model("sandia_torus.obj");
  print("sandia_torus.obj", run);
  expect_invariants(run);
  const double v0 = enclosed_volume(run.input), v1 = enclosed_volume(run.out.mesh);
  std::printf("[smooth] sandia_torus.obj volume %.9g -> %.9g (%+.4f %%)\n", v0, v1, 100 * (v1 - v0) / v0);
  EXPECT_GT(v0, 0);
  EXPECT_LT(std::abs(v1 - v0), 0.03 * v0);
  EXPECT_EQ(topology_of(run.out.mesh).euler, std::vector<long>{0});
}

// The smooth surface a --smooth run covers (its input in the mesher's domain: directional_bimba
// crosses itself in three places), with or without a bound on how far Loop's rules may move it
// (a fraction of the diagonal).
Smoothing smooth_surface_of(const std::string& model, double tolerance) {
  Smoothing run;
  SurfaceMesh input = read_mesh(test::model(model));
  (void)validate(input);
  MeshOptions mode;
  mode.smooth = true;
  run.input = prepare_domain(input, mode);
  run.strata = detect_strata(run.input, mode.sharp_angle() * test::kDegree, FeatureDetection::BoundaryOnly);
  SmoothingOptions options;
  options.max_deviation = tolerance * bounding_box_diagonal(run.input);
  run.out = smooth_patches(run.input, run.strata, options);
  return run;
}

TEST(SmoothPatches, BoundingRoundsKeepACoarseBentSurfaceNearItsInput) {
  // directional_bimba: 697 vertices, folds of up to 129 degrees. Loop's rules alone shrink it
  // 1.4 % of its diagonal away from its input (in the mesher's domain); split first where they
  // would move a vertex more than 0.75 %, it ends within 1 %, its farthest vertex moved less.
  const Smoothing plain = smooth_surface_of("directional_bimba.off", 0);
  const Smoothing bounded = smooth_surface_of("directional_bimba.off", 0.0075);
  print("directional_bimba.off, Loop's rules alone", plain);
  print("directional_bimba.off, bounded", bounded);
  expect_invariants(bounded);
  EXPECT_EQ(plain.out.bounding_rounds, 0);
  EXPECT_GE(bounded.out.bounding_rounds, 1);
  EXPECT_LE(bounded.out.bounding_rounds, SmoothingOptions{}.max_bounding_rounds);
  EXPECT_EQ(bounded.out.iterations, plain.out.iterations);
  const double diagonal = bounding_box_diagonal(bounded.input);
  EXPECT_EQ(plain.out.largest_limit_offset, 0);  // not measured without a bound
  EXPECT_GT(bounded.out.largest_limit_offset, 0);
  EXPECT_LE(bounded.out.largest_limit_offset, 0.0075 * diagonal);
  // No fold of the input survives as one: none of its edges bends past the sharp angle.
  EXPECT_LT(patch_bend(bounded.out.mesh, strata_after_smoothing(bounded.out)).max, 60);
  const double before = measure_surface_quality(plain.input, plain.out.mesh).hausdorff_relative;
  const double after = measure_surface_quality(bounded.input, bounded.out.mesh).hausdorff_relative;
  std::printf("[smooth] directional_bimba.off Hausdorff %.3f %% -> %.3f %% of the diagonal\n", 100 * before, 100 * after);
  EXPECT_GT(before, 0.012);
  EXPECT_LT(after, 0.01);
  EXPECT_EQ(topology_of(bounded.out.mesh).euler, topology_of(bounded.input).euler);
}

TEST(SmoothPatches, BoundingRoundsLeaveAFineTessellationAlone) {
  // sandia_torus's 4 608 vertices bend it little each: Loop's rules move none by 0.75 %, so the
  // bound splits nothing and the smoothing is Loop's alone, vertex for vertex.
  const Smoothing plain = smooth_surface_of("sandia_torus.obj", 0);
  const Smoothing bounded = smooth_surface_of("sandia_torus.obj", 0.0075);
  EXPECT_EQ(bounded.out.bounding_rounds, 0);
  EXPECT_EQ(bounded.out.mesh.triangles, plain.out.mesh.triangles);
  EXPECT_EQ(bounded.out.mesh.vertices, plain.out.mesh.vertices);
}

TEST(SmoothPatches, NonManifoldBoxKeepsItsWallsAndFaces) {
  const Smoothing run = smooth_model("sandia_non_manifold_box.obj");
  print("sandia_non_manifold_box.obj", run);
  expect_invariants(run);  // walks every non-manifold edge through the output's
  EXPECT_EQ(topology_of(run.input).non_manifold, 32u);
  EXPECT_GE(topology_of(run.out.mesh).non_manifold, 32u);
  EXPECT_GE(run.out.mesh.num_faces(), run.input.num_faces());
}

TEST(SmoothPatches, CurvedNonManifoldLayersKeepTheirJunctions) {
  // Three curved material layers meeting along ten non-manifold edges: those are creases, split
  // at midpoints, and every piece keeps all of its faces.
  const Smoothing run = smooth_model("openmeeg_HeadNNa1.obj");
  print("openmeeg_HeadNNa1.obj", run);
  expect_invariants(run);
  EXPECT_GT(run.out.iterations, 0);
  EXPECT_EQ(topology_of(run.input).non_manifold, 10u);
  EXPECT_GT(topology_of(run.out.mesh).non_manifold, 10u);
}

TEST(SmoothPatches, OpenTerrainKeepsItsBoundary) {
  const Smoothing run = smooth_model("gmsh_terrain.stl");
  print("gmsh_terrain.stl", run);
  expect_invariants(run);  // boundary edges are walked like creases
  EXPECT_EQ(topology_of(run.input).boundary, 126u);
  // Next to the held boundary the sector rule keeps the rows of new points from bunching up
  // (plain Loop takes this model's worst bend from 13.3 to 20.5 degrees there); it drops instead.
  const Strata after = strata_after_smoothing(run.out);
  EXPECT_LT(patch_bend(run.out.mesh, after).max, patch_bend(run.input, run.strata).max);
}

TEST(SmoothPatches, FlatBoxIsLeftAlone) {
  const Smoothing run = smooth_model("sandia_OneBox.obj");
  expect_invariants(run);
  EXPECT_EQ(run.out.iterations, 0);
  EXPECT_EQ(run.out.faces_split, 0u);
  EXPECT_EQ(run.out.mesh.vertices, run.input.vertices);
  EXPECT_EQ(run.out.mesh.triangles, run.input.triangles);
  EXPECT_EQ(run.out.mesh.face_group, run.input.face_group);
  EXPECT_EQ(run.out.mesh.face_line, run.input.face_line);
  EXPECT_EQ(run.out.sharp_edges.size(), 12u);  // the box's edges; face diagonals are flat
}

TEST(SmoothPatches, MaxFacesStopsBeforeExceeding) {
  SmoothingOptions options;
  options.max_faces = 50'000;  // one round makes 27610 faces, the next one would pass 100000
  const Smoothing run = smooth_model("igl_bunny.off", options);
  EXPECT_LE(run.out.mesh.num_faces(), 50'000u);
  EXPECT_GE(run.out.iterations, 1);
  EXPECT_LT(run.out.iterations, 6);
  expect_invariants(run);
}

TEST(SmoothPatches, RegionPairsFollowTheirFaces) {
  SurfaceMesh mesh = icosahedron();
  mesh.region_names = {"inside", "outside"};
  mesh.face_regions.assign(mesh.num_faces(), RegionPair{0, 1});
  mesh.face_regions[3] = RegionPair{1, 0};
  const Smoothing run = smooth_mesh(std::move(mesh), 80, {.max_iterations = 2});
  expect_invariants(run);
  // Face 3's children are the only ones with the swapped pair; they keep its line number.
  for (std::size_t f = 0; f < run.out.mesh.num_faces(); ++f) {
    EXPECT_EQ(run.out.mesh.face_regions[f] == (RegionPair{1, 0}), run.out.mesh.face_line[f] == 4u);
  }
}

}  // namespace
}  // namespace vorocrust
