// Every shared model read with the counts its README states: vertices (STL after welding),
// faces, boundary and non-manifold edges, components and genus. Non-manifold models keep all
// their faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <vector>

#include "test_support.hpp"
#include "vorocrust/mesh_info.hpp"
#include "vorocrust/read_mesh.hpp"
#include "vorocrust/validate.hpp"

namespace vorocrust {
namespace {

struct ModelFacts {
  const char* file;
  std::size_t vertices, faces, boundary_edges, non_manifold_edges, components;
  std::optional<int> genus;
  std::size_t self_intersections = 0;  // face pairs, confirmed independently with exact rationals
  std::size_t folded_faces = 0;        // faces folded over all their neighbours (io/unfold_faces.hpp)
};

std::ostream& operator<<(std::ostream& os, const ModelFacts& m) { return os << m.file; }

// From ../shared/models/README.md.
const ModelFacts kModels[] = {
    {"igl_bunny.off", 3485, 6966, 0, 0, 1, 0},
    {"directional_bimba.off", 697, 1390, 0, 0, 1, 0, 3},
    {"cgal_elephant.off", 2775, 5558, 0, 0, 1, 3},
    {"cgal_fandisk.off", 6475, 12946, 0, 0, 1, 0},
    {"cgal_joint.off", 221, 446, 0, 0, 1, 2},
    {"netgen_hinge.stl", 598, 1212, 0, 0, 1, 5},
    {"ajc_rocker-arm.obj", 10044, 20088, 0, 0, 1, 1},
    {"igl_fertility.off", 4494, 9000, 0, 0, 1, 4},
    {"igl_3holes.off", 3596, 7200, 0, 0, 1, 3},
    {"heptoroid_welded.off", 17878, 35840, 0, 0, 1, 22},
    {"cgal_bones.off", 2154, 4204, 0, 0, 26, 0, 366},
    {"cgal_knot2.off", 5760, 11520, 0, 0, 2, 2},
    {"cgal_cubes_edge_contact.off", 14, 24, 0, 1, 1, std::nullopt},
    {"openmeeg_HeadNNb3.obj", 2170, 4320, 0, 0, 5, 0},
    {"openmeeg_mne_sample_bem.obj", 1926, 3840, 0, 0, 3, 0},
    {"openmeeg_HeadNNa1.obj", 131, 258, 0, 10, 3, std::nullopt, 30},
    {"openmeeg_HeadNNc3.obj", 2607, 5350, 0, 150, 3, std::nullopt},
    {"cgal_polyhedral_complex_patches.obj", 1599, 3310, 0, 120, 1, std::nullopt},
    {"igl_camelhead.off", 11381, 22704, 56, 0, 1, std::nullopt, 5, 2},
    {"gmsh_terrain.stl", 1813, 3498, 126, 0, 1, std::nullopt},
    {"sandia_OneBox.obj", 8, 12, 0, 0, 1, 0},
    {"sandia_bird.obj", 2431, 4858, 0, 0, 1, 0},
    {"sandia_bracket.obj", 538, 1072, 0, 0, 1, 0},
    {"sandia_torus.obj", 4608, 9216, 0, 0, 1, 1},
    {"sandia_non_manifold_box.obj", 280, 586, 0, 32, 1, std::nullopt},
    {"sandia_cube_test_01.obj", 761, 1632, 0, 120, 1, std::nullopt},
    {"sandia_cube_test_02.obj", 583, 1231, 0, 73, 1, std::nullopt},
    {"sandia_cube_test_03.obj", 1895, 3782, 0, 0, 2, 0},
    {"sandia_cube_test_04.obj", 654, 1416, 0, 120, 1, std::nullopt},
};

class SharedModel : public ::testing::TestWithParam<ModelFacts> {};

TEST_P(SharedModel, CountsMatchTheModelsReadme) {
  const ModelFacts& m = GetParam();
  SurfaceMesh mesh = read_mesh(test::model(m.file));
  EXPECT_EQ(mesh.num_vertices(), m.vertices);
  EXPECT_EQ(mesh.num_faces(), m.faces);
  ASSERT_EQ(mesh.face_group.size(), m.faces);
  ASSERT_EQ(mesh.face_line.size(), m.faces);

  const MeshInfo info = mesh_info(mesh);
  EXPECT_EQ(info.boundary_edges, m.boundary_edges);
  EXPECT_EQ(info.non_manifold_edges, m.non_manifold_edges);
  EXPECT_EQ(info.components.size(), m.components);
  EXPECT_EQ(info.genus, m.genus);
}

// The README says orientation is consistent on every manifold edge, not that it points outward:
// validation must flip no single face, only whole closed shells that enclose negative volume.
TEST_P(SharedModel, ValidationOnlyTurnsWholeInwardShells) {
  const ModelFacts& m = GetParam();
  SurfaceMesh mesh = read_mesh(test::model(m.file));
  const MeshInfo before = mesh_info(mesh);
  ValidationOptions options;
  options.fix_folds = false;  // folds are the next test's
  const ValidationReport report = validate(mesh, options);
  // The only errors in the shared models are the self-intersections some of them really have.
  const Finding* crossing = report.find("self-intersection");
  EXPECT_EQ(crossing ? crossing->count : 0u, m.self_intersections) << m.file;
  for (const Finding& f : report.findings) {
    if (f.code != "self-intersection") {
      EXPECT_NE(f.severity, Finding::Severity::Error) << m.file << ": " << f.message;
    }
  }
  EXPECT_EQ(report.find("inconsistent-orientation"), nullptr) << m.file;
  EXPECT_EQ(report.find("non-orientable"), nullptr) << m.file;
  const MeshInfo after = mesh_info(mesh);
  std::size_t inward = 0;
  ASSERT_EQ(after.components.size(), before.components.size());
  for (std::size_t c = 0; c < after.components.size(); ++c) {
    if (!after.components[c].volume) continue;
    EXPECT_GT(*after.components[c].volume, 0.0) << m.file << " component " << c;
    EXPECT_NEAR(*after.components[c].volume, std::abs(*before.components[c].volume), 1e-9 * std::abs(*before.components[c].volume));
    inward += *before.components[c].volume < 0;
  }
  const Finding* turned = report.find("inward-shell");
  EXPECT_EQ(turned ? turned->count : 0u, inward) << m.file;
}

// Folds are unfolded in place, and the moves cross nothing: the shared models' only folded faces
// (igl_camelhead's two) cause all its self-intersections, which go with them.
TEST_P(SharedModel, FoldsAreUnfoldedWithoutNewCrossings) {
  const ModelFacts& m = GetParam();
  SurfaceMesh mesh = read_mesh(test::model(m.file));
  const ValidationReport report = validate(mesh);
  const Finding* folded = report.find("folded-face");
  ASSERT_EQ(folded ? folded->count : 0u, m.folded_faces) << m.file;
  if (folded) {
    EXPECT_EQ(folded->severity, Finding::Severity::Fixed) << folded->message;
  }
  const Finding* crossing = report.find("self-intersection");
  const std::size_t crossings = crossing ? crossing->count : 0u;
  if (m.folded_faces > 0) {
    EXPECT_LT(crossings, m.self_intersections) << m.file;
  } else {
    EXPECT_EQ(crossings, m.self_intersections) << m.file;
  }
}

// How far the flattest face is from a segment: twice its area over its longest edge squared.
double least_fullness(const SurfaceMesh& mesh) {
  double least = 1;
  for (const Triangle& t : mesh.triangles) {
    const Point &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    least = std::min(least, (b - a).cross(c - a).norm() / longest);
  }
  return least;
}

// Unfolded, a fold leaves its neighbourhood no more bent than the rest of the scan: igl_camelhead
// bends by at most 79 degrees away from its two folds, but moving one corner of each fold to the
// centroid of its ring left 147 and 124 there, creases so sharp the refinement could not cover them.
// Nor is a face left flatter than the scan's flattest: vertex 901 moved to 3.7e-6 from the line
// of its face's other corners made a corner of six creases with balls down to 2e-8 across about it
// (302 000 balls in all; 204 000 since).
TEST(SharedModelFolds, UnfoldingLeavesNoBendSharperThanTheScansOwn) {
  SurfaceMesh mesh = read_mesh(test::model("igl_camelhead.off"));
  const double scans_flattest = least_fullness(mesh);
  (void)validate(mesh);
  EXPECT_GE(least_fullness(mesh), scans_flattest);
  const auto normal = [&](Index f) {
    const Triangle& t = mesh.triangles[f];
    return Point((mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).normalized());
  };
  std::map<std::pair<Index, Index>, std::vector<Index>> faces_of_edge;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const Index a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
      faces_of_edge[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  }
  double largest = 0;
  for (const auto& [edge, faces] : faces_of_edge) {
    if (faces.size() != 2) continue;
    largest = std::max(largest, std::acos(std::clamp(normal(faces[0]).dot(normal(faces[1])), -1.0, 1.0)) * 180 / std::numbers::pi);
  }
  EXPECT_LT(largest, 80.0);
}

INSTANTIATE_TEST_SUITE_P(Models, SharedModel, ::testing::ValuesIn(kModels),
                         [](const ::testing::TestParamInfo<ModelFacts>& info) {
                           std::string name = info.param.file;
                           for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return name;
                         });

TEST(SharedModelGroups, ObjGroupsAreKeptWithTheirFaces) {
  const SurfaceMesh complex = read_mesh(test::model("cgal_polyhedral_complex_patches.obj"));
  ASSERT_EQ(complex.groups.size(), 6u);
  EXPECT_EQ(complex.groups[0].name, "patch-01");
  EXPECT_EQ(complex.groups[5].name, "patch-30");

  const SurfaceMesh head = read_mesh(test::model("openmeeg_HeadNNc3.obj"));
  const MeshInfo info = mesh_info(head);
  ASSERT_EQ(info.groups.size(), 5u);
  std::size_t total = 0;
  for (const GroupInfo& g : info.groups) {
    EXPECT_GT(g.faces, 0u) << g.name;
    total += g.faces;
  }
  EXPECT_EQ(total, 5350u);
  EXPECT_EQ(info.groups[0].name, "cut");
}

TEST(SharedModelGroups, SeveralFilesMergeOneGroupEach) {
  const SurfaceMesh merged = read_meshes({test::model("sandia_OneBox.obj"), test::model("cgal_joint.off")});
  ASSERT_EQ(merged.groups.size(), 2u);
  EXPECT_EQ(merged.groups[0].name, "sandia_OneBox");
  EXPECT_EQ(merged.groups[1].name, "cgal_joint");
  EXPECT_EQ(merged.num_faces(), 12u + 446u);
  EXPECT_EQ(merged.num_vertices(), 8u + 221u);
  const MeshInfo info = mesh_info(merged);
  EXPECT_EQ(info.components.size(), 2u);
  EXPECT_EQ(info.genus, 2);
}

}  // namespace
}  // namespace vorocrust
