// The MeshLab adapter's conversions, on layers built in memory: what a layer becomes as the
// library's input (faces kept, deleted ones skipped, selection as groups, layers welded, bad
// coordinates refused) and what the balls become as a layer.
#include <common/meshmodel.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "layers_to_surface.hpp"
#include "result_layers.hpp"
#include "vorocrust/error.hpp"

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

}  // namespace
