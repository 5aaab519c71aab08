#include <common/meshmodel.h>

#include "result_layers.hpp"

#include <QFileInfo>

namespace vorocrust::meshlab {

namespace {

vcg::Color4b stratum_colour(StratumType type) {
  switch (type) {
    case StratumType::Corner: return {220, 40, 40, 255};
    case StratumType::Crease: return {235, 190, 40, 255};
    case StratumType::Patch: return {120, 150, 200, 255};
  }
  return {128, 128, 128, 255};
}

}  // namespace

MeshModel* add_balls_layer(MeshDocument& md, const std::vector<Ball>& balls, const MeshModel& source) {
  // MeshLab's layer list shows a label as a file name without its extension, cutting it at its
  // last dot: the name has none.
  const QString name = QFileInfo(source.label()).completeBaseName().replace('.', '_') + " VoroCrust balls";
  MeshModel* layer = md.addNewMesh("", name, true);
  try {
    layer->updateDataMask(MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR);
    CMeshO& cm = layer->cm;
    cm.Tr = source.cm.Tr;
    using Allocator = vcg::tri::Allocator<CMeshO>;
    auto radius = Allocator::GetPerVertexAttribute<float>(cm, kRadiusAttribute);
    auto stratum_type = Allocator::GetPerVertexAttribute<float>(cm, kStratumTypeAttribute);
    auto stratum_index = Allocator::GetPerVertexAttribute<float>(cm, kStratumIndexAttribute);
    auto v = Allocator::AddVertices(cm, balls.size());
    for (const Ball& ball : balls) {
      v->P() = CMeshO::CoordType(CMeshO::ScalarType(ball.center.x()), CMeshO::ScalarType(ball.center.y()),
                                 CMeshO::ScalarType(ball.center.z()));
      v->Q() = float(ball.radius);
      v->C() = stratum_colour(ball.type);
      radius[v] = float(ball.radius);
      stratum_type[v] = float(static_cast<int>(ball.type));
      stratum_index[v] = float(ball.stratum);
      ++v;
    }
    vcg::tri::UpdateBounding<CMeshO>::Box(cm);
  } catch (...) {
    md.delMesh(layer);
    throw;
  }
  return layer;
}

ResultLayers add_result_layers(MeshDocument& md, const MeshResult& result, Stage stage, const MeshModel& source) {
  ResultLayers added;
  try {
    added.balls = add_balls_layer(md, result.balls, source);
    if (stage == Stage::Cells) {
      // The surface and seeds layers go here, once MeshResult carries them.
    }
  } catch (...) {
    if (added.balls) md.delMesh(added.balls);
    throw;
  }
  return added;
}

}  // namespace vorocrust::meshlab
