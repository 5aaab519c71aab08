// Feature detection on shapes whose corners, creases and patches are known.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "features/strata.hpp"
#include "io/enclose_in_box.hpp"
#include "test_support.hpp"
#include "vorocrust/read_mesh.hpp"
#include "vorocrust/validate.hpp"

namespace vorocrust {
namespace {


Strata strata_of(const std::string& model, double degrees = 30,
                 FeatureDetection detection = FeatureDetection::SharpAndBoundary) {
  SurfaceMesh mesh = read_mesh(test::model(model));
  (void)validate(mesh);
  return detect_strata(mesh, degrees * test::kDegree, detection);
}

// Invariants every detection must satisfy, whatever the model.
void expect_consistent(const Strata& s) {
  for (std::size_t e = 0; e < s.topology.num_edges(); ++e) {
    EXPECT_EQ(s.sharp_edge[e], s.edge_crease[e] != Strata::kNone) << "edge " << e;
    if (s.topology.valence(e) != 2) {
      EXPECT_TRUE(s.sharp_edge[e]);
    }
  }
  for (std::size_t k = 0; k < s.creases.size(); ++k) {
    const Crease& c = s.creases[k];
    ASSERT_EQ(c.edges.size() + (c.closed ? 0 : 1), c.vertices.size()) << "crease " << k;
    if (!c.closed) {
      EXPECT_NE(s.vertex_corner[c.vertices.front()], Strata::kNone);
      EXPECT_NE(s.vertex_corner[c.vertices.back()], Strata::kNone);
    }
    for (std::size_t i = 0; i < c.edges.size(); ++i) {
      const auto [a, b] = s.topology.edges[c.edges[i]];
      const Index u = c.vertices[i], v = c.vertices[(i + 1) % c.vertices.size()];
      EXPECT_TRUE((a == u && b == v) || (a == v && b == u)) << "crease " << k << " edge " << i;
      EXPECT_EQ(s.edge_crease[c.edges[i]], static_cast<std::int32_t>(k));
      if (i > 0) {
        EXPECT_EQ(s.vertex_corner[u], Strata::kNone) << "a corner inside crease " << k;
      }
    }
  }
  // Faces across a non-sharp edge share their patch.
  for (std::size_t e = 0; e < s.topology.num_edges(); ++e) {
    if (s.sharp_edge[e]) continue;
    const auto f = s.topology.faces_of(e);
    EXPECT_EQ(s.face_patch[f[0]], s.face_patch[f[1]]);
  }
}

TEST(Strata, CubeHasEightCornersTwelveCreasesSixPatches) {
  const Strata s = strata_of("sandia_OneBox.obj");
  expect_consistent(s);
  EXPECT_EQ(s.corners.size(), 8u);
  EXPECT_EQ(s.creases.size(), 12u);
  EXPECT_EQ(s.num_patches, 6u);
  for (const auto& creases : s.corner_creases) EXPECT_EQ(creases.size(), 3u);
  for (const auto& patches : s.corner_patches) EXPECT_EQ(patches.size(), 3u);
  for (const auto& patches : s.crease_patches) EXPECT_EQ(patches.size(), 2u);
}

TEST(Strata, SmoothTorusHasOnePatchAndNoFeatures) {
  const Strata s = strata_of("sandia_torus.obj");
  expect_consistent(s);
  EXPECT_TRUE(s.corners.empty());
  EXPECT_TRUE(s.creases.empty());
  EXPECT_EQ(s.num_patches, 1u);
}

TEST(Strata, NonManifoldEdgesAreCreasesEndingInCorners) {
  const Strata s = strata_of("cgal_cubes_edge_contact.off");
  expect_consistent(s);
  std::size_t nm_creases = 0;
  for (const Crease& c : s.creases) {
    if (s.topology.valence(c.edges[0]) == 4) {
      ++nm_creases;
      EXPECT_EQ(c.edges.size(), 1u);
    }
  }
  EXPECT_EQ(nm_creases, 1u);
  EXPECT_EQ(s.num_patches, 12u);  // each cube face is its own patch
}

TEST(Strata, OpenBoundaryIsACycleCrease) {
  const Strata s = strata_of("igl_camelhead.off", 60);
  expect_consistent(s);
  std::size_t boundary_edges = 0;
  for (const Crease& c : s.creases) {
    for (Index e : c.edges) boundary_edges += s.topology.is_boundary(e);
  }
  EXPECT_EQ(boundary_edges, 56u);
}

TEST(Strata, ASmoothScanHasNoFeaturesWhereTheRulesFindMany) {
  // The decimated bunny bends past 60 degrees across 59 edges: creases by the paper's rules.
  const Strata by_angle = strata_of("igl_bunny.off", 60);
  EXPECT_GT(by_angle.corners.size(), 100u);
  const Strata smooth = strata_of("igl_bunny.off", 60, FeatureDetection::BoundaryOnly);
  expect_consistent(smooth);
  EXPECT_TRUE(smooth.corners.empty());
  EXPECT_TRUE(smooth.creases.empty());
  EXPECT_EQ(smooth.num_patches, 1u);
}

TEST(Strata, ASmoothSurfaceKeepsItsBoundaryAndNonManifoldEdges) {
  // Taken as smooth, a surface still has the edges where other than two faces meet, and the
  // corners where they end or branch; the fold between the cubes' faces is no longer a crease.
  for (const char* model : {"igl_camelhead.off", "cgal_cubes_edge_contact.off"}) {
    SCOPED_TRACE(model);
    const Strata rules = strata_of(model, 60);
    const Strata smooth = strata_of(model, 60, FeatureDetection::BoundaryOnly);
    expect_consistent(smooth);
    for (std::size_t e = 0; e < smooth.topology.num_edges(); ++e) {
      EXPECT_EQ(smooth.sharp_edge[e], smooth.topology.valence(e) != 2) << "edge " << e;
      if (smooth.sharp_edge[e]) {
        EXPECT_TRUE(rules.sharp_edge[e]);
      }
    }
  }
  const Strata camel = strata_of("igl_camelhead.off", 60, FeatureDetection::BoundaryOnly);
  std::size_t crease_edges = 0;
  for (const Crease& c : camel.creases) crease_edges += c.edges.size();
  EXPECT_EQ(crease_edges, 56u);  // the rim of the open neck, all of it
  EXPECT_EQ(camel.num_patches, 1u);
  const Strata cubes = strata_of("cgal_cubes_edge_contact.off", 30, FeatureDetection::BoundaryOnly);
  EXPECT_EQ(cubes.creases.size(), 1u);  // the edge the cubes share, between its two corners
  EXPECT_EQ(cubes.corners.size(), 2u);
  EXPECT_EQ(cubes.num_patches, 2u);
}

TEST(Strata, TheSidesOfABoxAroundASmoothSurfaceKeepTheirEdges) {
  // The camel's open neck puts it in a box. Taken as smooth, its own edges are sharp only on the
  // rim; the box's twelve edges still bend past the angle and stay creases between eight corners.
  SurfaceMesh camel = read_mesh(test::model("igl_camelhead.off"));
  (void)validate(camel);
  ASSERT_TRUE(needs_box(camel));
  const SurfaceMesh boxed = enclose_in_box(camel, default_box(camel));
  const std::vector<bool> box = box_faces(boxed);
  ASSERT_EQ(std::count(box.begin(), box.end(), true), 12);
  const Strata s = detect_strata(boxed, 60 * test::kDegree, FeatureDetection::BoundaryOnly, box);
  expect_consistent(s);
  std::size_t box_edges = 0, camel_edges = 0;
  for (std::size_t e = 0; e < s.topology.num_edges(); ++e) {
    if (!s.sharp_edge[e]) continue;
    (box[s.topology.faces_of(e)[0]] ? box_edges : camel_edges) += 1;
  }
  EXPECT_EQ(box_edges, 12u);    // the cube's edges; not the diagonals of its sides
  EXPECT_EQ(camel_edges, 56u);  // the rim, as without the box
  EXPECT_EQ(s.corners.size(), 8u + strata_of("igl_camelhead.off", 60, FeatureDetection::BoundaryOnly).corners.size());
  EXPECT_EQ(s.num_patches, 7u);  // the camel, and the box's six sides
}

TEST(Strata, SharpCadModelsAreConsistentAndAngleMonotone) {
  for (const char* model : {"cgal_fandisk.off", "cgal_joint.off", "sandia_bracket.obj", "netgen_hinge.stl",
                            "sandia_non_manifold_box.obj", "cgal_polyhedral_complex_patches.obj"}) {
    SCOPED_TRACE(model);
    const Strata fine = strata_of(model, 20);
    const Strata coarse = strata_of(model, 50);
    expect_consistent(fine);
    expect_consistent(coarse);
    std::size_t sharp_fine = 0, sharp_coarse = 0;
    for (bool b : fine.sharp_edge) sharp_fine += b;
    for (bool b : coarse.sharp_edge) sharp_coarse += b;
    EXPECT_GE(sharp_fine, sharp_coarse);  // a smaller theta# finds every edge a larger one finds
    EXPECT_GT(sharp_coarse, 0u);
  }
}

}  // namespace
}  // namespace vorocrust
