// The MeshLab adapter's conversions, on layers built in memory: what a layer becomes as the
// library's input (faces kept, deleted ones skipped, selection as groups, layers welded, bad
// coordinates refused) and what the balls, the surface and the seeds become as layers.
#include <common/meshmodel.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "layers_to_surface.hpp"
#include "result_layers.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/quality.hpp"

namespace {

using vorocrust::Error;
using vorocrust::meshlab::surface_from_layers;
using Allocator = vcg::tri::Allocator<CMeshO>;

// Adds vertices at the given points and faces over them (indices into this call's vertices).
void add(CMeshO& cm, const std::vector<std::array<float, 3>>& points, const std::vector<std::array<int, 3>>& faces) {
  const std::size_t first = cm.vert.size();
  auto v = Allocator::AddVertices(cm, points.size());
  for (const auto& p : points) (v++)->P() = CMeshO::CoordType(p[0], p[1], p[2]);
  for (const auto& f : faces) {
    Allocator::AddFace(cm, &cm.vert[first + f[0]], &cm.vert[first + f[1]], &cm.vert[first + f[2]]);
  }
}

// Three triangles around the edge (0,0,0)-(1,0,0): a non-manifold edge.
MeshModel* fan_of_three(MeshDocument& md, const QString& label) {
  MeshModel* m = md.addNewMesh("", label);
  add(m->cm, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, -1, 0}}, {{0, 1, 2}, {0, 1, 3}, {0, 1, 4}});
  return m;
}

Error::Kind kind_of_error(const std::vector<const MeshModel*>& layers, std::string& message) {
  try {
    surface_from_layers(layers);
  } catch (const Error& e) {
    message = e.what();
    return e.kind();
  }
  return Error::Kind::Internal;
}

TEST(LayersToSurface, KeepsNonManifoldFacesAndSkipsDeletedOnes) {
  MeshDocument md;
  MeshModel* m = fan_of_three(md, "fan");
  add(m->cm, {{5, 5, 5}, {6, 5, 5}, {5, 6, 5}}, {{0, 1, 2}});  // to be deleted, with one of its vertices
  Allocator::DeleteFace(m->cm, m->cm.face[3]);
  Allocator::DeleteVertex(m->cm, m->cm.vert[7]);

  const vorocrust::SurfaceMesh s = surface_from_layers({m});
  ASSERT_EQ(s.num_faces(), 3u);
  ASSERT_EQ(s.num_vertices(), 7u);  // the 5 of the fan and the two live ones of the deleted face
  for (std::size_t f = 0; f < 3; ++f) {
    for (int k = 0; k < 3; ++k) {
      const auto& p = m->cm.face[f].cP(k);
      EXPECT_EQ(s.vertices[s.triangles[f][k]], vorocrust::Point(p[0], p[1], p[2])) << "face " << f;
    }
  }
  EXPECT_EQ(s.triangles[2], (vorocrust::Triangle{0, 1, 4}));
  ASSERT_EQ(s.groups.size(), 1u);
  EXPECT_EQ(s.groups[0].name, "fan");
}

TEST(LayersToSurface, SelectedFacesFormTheirOwnGroup) {
  MeshDocument md;
  MeshModel* m = fan_of_three(md, "fan");
  m->cm.face[1].SetS();
  const vorocrust::SurfaceMesh s = surface_from_layers({m});
  ASSERT_EQ(s.groups.size(), 2u);
  EXPECT_EQ(s.groups[s.face_group[0]].name, "fan");
  EXPECT_EQ(s.groups[s.face_group[1]].name, "fan/selected");
  EXPECT_EQ(s.face_group[2], s.face_group[0]);

  for (CFaceO& f : m->cm.face) f.SetS();  // all selected: one group, named for it
  const vorocrust::SurfaceMesh all = surface_from_layers({m});
  ASSERT_EQ(all.groups.size(), 1u);
  EXPECT_EQ(all.groups[0].name, "fan/selected");
}

TEST(LayersToSurface, LayersShareVerticesWithExactlyEqualCoordinates) {
  MeshDocument md;
  MeshModel* a = md.addNewMesh("", "a");
  add(a->cm, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
  MeshModel* b = md.addNewMesh("", "b");
  add(b->cm, {{1, 0, 0}, {0, 1, 0}, {1, 1, 0.5f}, {1.0000001f, 0, 0}}, {{0, 2, 1}, {3, 2, 1}});
  const vorocrust::SurfaceMesh s = surface_from_layers({a, b});
  EXPECT_EQ(s.num_vertices(), 5u);  // (1,0,0) and (0,1,0) shared; the nearly equal one is not
  ASSERT_EQ(s.num_faces(), 3u);
  EXPECT_EQ(s.triangles[1], (vorocrust::Triangle{1, 3, 2}));
  EXPECT_EQ(s.triangles[2], (vorocrust::Triangle{4, 3, 2}));
  ASSERT_EQ(s.groups.size(), 2u);
  EXPECT_EQ(s.groups[s.face_group[2]].name, "b");
}

TEST(LayersToSurface, RefusesNonFiniteCoordinatesAndLayersWithoutFaces) {
  MeshDocument md;
  MeshModel* m = fan_of_three(md, "fan");
  m->cm.vert[3].P()[1] = std::numeric_limits<float>::quiet_NaN();
  std::string message;
  EXPECT_EQ(kind_of_error({m}, message), Error::Kind::InvalidGeometry);
  EXPECT_NE(message.find("vertex 3 of layer \"fan\" has a NaN or infinite coordinate"), std::string::npos) << message;

  MeshModel* points = md.addNewMesh("", "points");
  add(points->cm, {{0, 0, 0}, {1, 0, 0}}, {});
  EXPECT_EQ(kind_of_error({points}, message), Error::Kind::InvalidGeometry);
  EXPECT_NE(message.find("layer \"points\" has no faces"), std::string::npos) << message;
}

TEST(ResultLayers, BallsBecomeAPointLayerWithTheirRadiiAndStrata) {
  MeshDocument md;
  MeshModel* source = fan_of_three(md, "fan.v2.off");
  source->cm.Tr.SetTranslate(1, 2, 3);
  const std::vector<vorocrust::Ball> balls{
      {{0, 0, 0}, 0.5, vorocrust::StratumType::Corner, 0},
      {{0.5, 0, 0}, 0.25, vorocrust::StratumType::Crease, 2},
      {{0.2, 0.2, 0}, 0.125, vorocrust::StratumType::Patch, 7}};
  MeshModel* layer = vorocrust::meshlab::add_balls_layer(md, balls, *source);
  EXPECT_EQ(md.mm(), layer);
  EXPECT_EQ(layer->label(), "fan_v2 VoroCrust balls");
  EXPECT_EQ(md.size(), 2);
  const CMeshO& cm = layer->cm;
  ASSERT_EQ(cm.vn, 3);
  EXPECT_EQ(cm.fn, 0);
  EXPECT_EQ(cm.Tr, source->cm.Tr);
  EXPECT_TRUE(layer->hasDataMask(MeshModel::MM_VERTQUALITY));
  EXPECT_TRUE(layer->hasDataMask(MeshModel::MM_VERTCOLOR));
  auto radius = Allocator::FindPerVertexAttribute<float>(layer->cm, vorocrust::meshlab::kRadiusAttribute);
  auto type = Allocator::FindPerVertexAttribute<float>(layer->cm, vorocrust::meshlab::kStratumTypeAttribute);
  auto index = Allocator::FindPerVertexAttribute<float>(layer->cm, vorocrust::meshlab::kStratumIndexAttribute);
  ASSERT_TRUE(Allocator::IsValidHandle<float>(layer->cm, radius));
  ASSERT_TRUE(Allocator::IsValidHandle<float>(layer->cm, type));
  ASSERT_TRUE(Allocator::IsValidHandle<float>(layer->cm, index));
  for (std::size_t k = 0; k < balls.size(); ++k) {
    const CVertexO& v = cm.vert[k];
    EXPECT_EQ(v.cP(), CMeshO::CoordType(balls[k].center.x(), balls[k].center.y(), balls[k].center.z()));
    EXPECT_EQ(v.cQ(), float(balls[k].radius));
    EXPECT_EQ(radius[k], float(balls[k].radius));
    EXPECT_EQ(type[k], float(static_cast<int>(balls[k].type)));
    EXPECT_EQ(index[k], float(balls[k].stratum));
  }
  EXPECT_NE(cm.vert[0].cC(), cm.vert[1].cC());  // colours tell the stratum types apart
  EXPECT_NE(cm.vert[1].cC(), cm.vert[2].cC());
  EXPECT_FALSE(cm.bbox.IsNull());
}

// A tetrahedron whose faces separate three region pairs: material 1 from the outside (two
// faces), material 2 from the outside, material 2 from material 1.
vorocrust::SurfaceMesh labelled_tetrahedron() {
  vorocrust::SurfaceMesh s;
  s.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  s.groups.push_back({"surface", ""});
  for (const vorocrust::Triangle& t : {vorocrust::Triangle{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}) {
    s.add_triangle(t, 0);
  }
  s.face_regions = {{1, 0}, {2, 0}, {1, 0}, {2, 1}};
  s.region_names = {"outside", "material1", "material2"};
  return s;
}

TEST(ResultLayers, TheSurfaceKeepsItsFacesWithRegionPairsQualityAndAColourPerPair) {
  MeshDocument md;
  MeshModel* source = fan_of_three(md, "tet.off");
  const vorocrust::SurfaceMesh s = labelled_tetrahedron();
  MeshModel* layer = vorocrust::meshlab::add_surface_layer(md, s, *source);
  EXPECT_EQ(layer->label(), "tet VoroCrust surface");
  EXPECT_TRUE(layer->hasDataMask(MeshModel::MM_FACEQUALITY));
  EXPECT_TRUE(layer->hasDataMask(MeshModel::MM_FACECOLOR));
  CMeshO& cm = layer->cm;
  ASSERT_EQ(cm.vn, 4);
  ASSERT_EQ(cm.fn, 4);
  for (int v = 0; v < 4; ++v) {
    EXPECT_EQ(cm.vert[v].cP(), CMeshO::CoordType(s.vertices[v].x(), s.vertices[v].y(), s.vertices[v].z()));
  }
  auto back = Allocator::FindPerFaceAttribute<float>(cm, vorocrust::meshlab::kBackRegionAttribute);
  auto front = Allocator::FindPerFaceAttribute<float>(cm, vorocrust::meshlab::kFrontRegionAttribute);
  ASSERT_TRUE(Allocator::IsValidHandle<float>(cm, back));
  ASSERT_TRUE(Allocator::IsValidHandle<float>(cm, front));
  const std::vector<double> quality = vorocrust::triangle_qualities(s);
  for (int f = 0; f < 4; ++f) {
    for (int k = 0; k < 3; ++k) EXPECT_EQ(vcg::tri::Index(cm, cm.face[f].cV(k)), s.triangles[f][k]) << f;
    EXPECT_EQ(back[f], float(s.face_regions[f].back));
    EXPECT_EQ(front[f], float(s.face_regions[f].front));
    EXPECT_EQ(cm.face[f].cQ(), float(quality[f]));
  }
  EXPECT_NEAR(cm.face[3].cQ(), 1.0f, 1e-6f);  // the equilateral face
  EXPECT_LT(cm.face[0].cQ(), 0.9f);
  // One colour per region pair: faces 0 and 2 share theirs, the other pairs differ.
  EXPECT_EQ(cm.face[0].cC(), cm.face[2].cC());
  EXPECT_NE(cm.face[0].cC(), cm.face[1].cC());
  EXPECT_NE(cm.face[0].cC(), cm.face[3].cC());
  EXPECT_NE(cm.face[1].cC(), cm.face[3].cC());
  EXPECT_FALSE(cm.bbox.IsNull());
  EXPECT_NEAR(cm.face[3].cN().Norm(), 1.0f, 1e-6f);  // normals for MeshLab's shading
}

TEST(ResultLayers, SeedsBecomeAPointLayerWithLabelKindAndRadius) {
  MeshDocument md;
  MeshModel* source = fan_of_three(md, "fan.off");
  const std::vector<vorocrust::Seed> seeds{{{0, 0, 1}, 0, 0.5, vorocrust::SeedKind::Surface},
                                           {{0, 0, -1}, 1, 0.5, vorocrust::SeedKind::Surface},
                                           {{0, 0, -3}, 2, 0.75, vorocrust::SeedKind::Interior},
                                           {{0, 0, 9}, 0, 2.5, vorocrust::SeedKind::Outside}};
  MeshModel* layer = vorocrust::meshlab::add_seeds_layer(md, seeds, *source);
  EXPECT_EQ(layer->label(), "fan VoroCrust seeds");
  CMeshO& cm = layer->cm;
  ASSERT_EQ(cm.vn, 4);
  EXPECT_EQ(cm.fn, 0);
  auto label = Allocator::FindPerVertexAttribute<float>(cm, vorocrust::meshlab::kLabelAttribute);
  auto kind = Allocator::FindPerVertexAttribute<float>(cm, vorocrust::meshlab::kSeedKindAttribute);
  auto radius = Allocator::FindPerVertexAttribute<float>(cm, vorocrust::meshlab::kRadiusAttribute);
  ASSERT_TRUE(Allocator::IsValidHandle<float>(cm, label));
  ASSERT_TRUE(Allocator::IsValidHandle<float>(cm, kind));
  ASSERT_TRUE(Allocator::IsValidHandle<float>(cm, radius));
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    const CVertexO& v = cm.vert[k];
    EXPECT_EQ(v.cP(), CMeshO::CoordType(0, 0, float(seeds[k].position.z())));
    EXPECT_EQ(v.cQ(), float(seeds[k].radius));
    EXPECT_EQ(radius[k], float(seeds[k].radius));
    EXPECT_EQ(label[k], float(seeds[k].region));
    EXPECT_EQ(kind[k], float(static_cast<int>(seeds[k].kind)));
  }
  // Colour by label: both outside seeds alike, each material its own.
  EXPECT_EQ(cm.vert[0].cC(), cm.vert[3].cC());
  EXPECT_NE(cm.vert[0].cC(), cm.vert[1].cC());
  EXPECT_NE(cm.vert[1].cC(), cm.vert[2].cC());
  EXPECT_NE(cm.vert[0].cC(), cm.vert[2].cC());
}

TEST(ResultLayers, ARunToTheSurfaceAddsTheSurfaceAndTheSeedsWithTheSurfaceCurrent) {
  MeshDocument md;
  MeshModel* source = fan_of_three(md, "tet.off");
  vorocrust::MeshResult result;
  result.surface = labelled_tetrahedron();
  result.seeds = {{{0.2, 0.2, 0.2}, 1, 0.1, vorocrust::SeedKind::Surface}};
  result.balls = {{{0, 0, 0}, 0.5, vorocrust::StratumType::Corner, 0}};
  const auto added = vorocrust::meshlab::add_result_layers(md, result, vorocrust::Stage::Surface, *source);
  EXPECT_EQ(added.balls, nullptr);
  ASSERT_NE(added.surface, nullptr);
  ASSERT_NE(added.seeds, nullptr);
  EXPECT_EQ(md.size(), 3);
  EXPECT_EQ(md.mm(), added.surface);
  EXPECT_EQ(added.surface->cm.fn, 4);
  EXPECT_EQ(added.seeds->cm.vn, 1);

  const auto balls = vorocrust::meshlab::add_result_layers(md, result, vorocrust::Stage::Balls, *source);
  ASSERT_NE(balls.balls, nullptr);
  EXPECT_EQ(balls.surface, nullptr);
  EXPECT_EQ(md.size(), 4);
}

}  // namespace
