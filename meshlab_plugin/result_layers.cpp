#include <common/meshmodel.h>

#include "result_layers.hpp"

#include <QFileInfo>

#include <algorithm>
#include <array>

#include "vorocrust/quality.hpp"

namespace vorocrust::meshlab {

namespace {

using Allocator = vcg::tri::Allocator<CMeshO>;

vcg::Color4b stratum_colour(StratumType type) {
  switch (type) {
    case StratumType::Corner: return {220, 40, 40, 255};
    case StratumType::Crease: return {235, 190, 40, 255};
    case StratumType::Patch: return {120, 150, 200, 255};
  }
  return {128, 128, 128, 255};
}

// Colours told apart at a glance, for regions and region pairs; none of them grey, which marks
// the outside.
const std::array<vcg::Color4b, 10> kPalette{{{70, 130, 200, 255},
                                                 {230, 120, 40, 255},
                                                 {80, 170, 80, 255},
                                                 {200, 60, 70, 255},
                                                 {150, 100, 190, 255},
                                                 {150, 100, 70, 255},
                                                 {220, 120, 180, 255},
                                                 {190, 190, 50, 255},
                                                 {60, 190, 200, 255},
                                                 {40, 70, 140, 255}}};
const vcg::Color4b kOutsideColour{160, 160, 160, 255};

vcg::Color4b palette_colour(std::size_t k) { return kPalette[k % kPalette.size()]; }

vcg::Color4b label_colour(std::int32_t label) {
  return label > 0 ? palette_colour(static_cast<std::size_t>(label - 1)) : kOutsideColour;
}

CMeshO::CoordType to_coord(const Point& p) {
  return {CMeshO::ScalarType(p.x()), CMeshO::ScalarType(p.y()), CMeshO::ScalarType(p.z())};
}

// Adds the layer "SOURCE VoroCrust WHAT" with the given data mask and the source's
// transformation, lets `fill` build its contents, and sets its bounding box (and its normals,
// when it has faces). A failing `fill` takes the layer away again.
template <class Fill>
MeshModel* add_layer(MeshDocument& md, const MeshModel& source, const char* what, int data_mask, Fill&& fill) {
  // MeshLab's layer list shows a label as a file name without its extension, cutting it at its
  // last dot: the name has none.
  const QString name = QFileInfo(source.label()).completeBaseName().replace('.', '_') + " VoroCrust " + what;
  MeshModel* layer = md.addNewMesh("", name, true);
  try {
    layer->updateDataMask(data_mask);
    layer->cm.Tr = source.cm.Tr;
    fill(layer->cm);
    layer->UpdateBoxAndNormals();
  } catch (...) {
    md.delMesh(layer);
    throw;
  }
  return layer;
}

}  // namespace

MeshModel* add_balls_layer(MeshDocument& md, const std::vector<Ball>& balls, const MeshModel& source) {
  return add_layer(md, source, "balls", MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR, [&](CMeshO& cm) {
    auto radius = Allocator::GetPerVertexAttribute<float>(cm, kRadiusAttribute);
    auto stratum_type = Allocator::GetPerVertexAttribute<float>(cm, kStratumTypeAttribute);
    auto stratum_index = Allocator::GetPerVertexAttribute<float>(cm, kStratumIndexAttribute);
    auto v = Allocator::AddVertices(cm, balls.size());
    for (const Ball& ball : balls) {
      v->P() = to_coord(ball.center);
      v->Q() = float(ball.radius);
      v->C() = stratum_colour(ball.type);
      radius[v] = float(ball.radius);
      stratum_type[v] = float(static_cast<int>(ball.type));
      stratum_index[v] = float(ball.stratum);
      ++v;
    }
  });
}

MeshModel* add_surface_layer(MeshDocument& md, const SurfaceMesh& surface, const MeshModel& source) {
  const auto region_pair = [&](std::size_t f) { return surface.has_regions() ? surface.face_regions[f] : RegionPair{}; };
  const auto pair_key = [](const RegionPair& p) { return std::pair(p.back, p.front); };
  std::vector<std::pair<std::int32_t, std::int32_t>> pairs;  // present, in increasing order
  for (std::size_t f = 0; f < surface.num_faces(); ++f) pairs.push_back(pair_key(region_pair(f)));
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  const std::vector<double> quality = triangle_qualities(surface);

  return add_layer(md, source, "surface", MeshModel::MM_FACEQUALITY | MeshModel::MM_FACECOLOR, [&](CMeshO& cm) {
    auto back = Allocator::GetPerFaceAttribute<float>(cm, kBackRegionAttribute);
    auto front = Allocator::GetPerFaceAttribute<float>(cm, kFrontRegionAttribute);
    auto v = Allocator::AddVertices(cm, surface.num_vertices());
    for (const Point& p : surface.vertices) (v++)->P() = to_coord(p);
    auto f = Allocator::AddFaces(cm, surface.num_faces());
    for (std::size_t k = 0; k < surface.num_faces(); ++k, ++f) {
      for (int corner = 0; corner < 3; ++corner) f->V(corner) = &cm.vert[surface.triangles[k][corner]];
      const RegionPair regions = region_pair(k);
      back[f] = float(regions.back);
      front[f] = float(regions.front);
      f->Q() = float(quality[k]);
      const auto rank = std::lower_bound(pairs.begin(), pairs.end(), pair_key(regions)) - pairs.begin();
      f->C() = palette_colour(static_cast<std::size_t>(rank));
    }
  });
}

MeshModel* add_seeds_layer(MeshDocument& md, const std::vector<Seed>& seeds, const MeshModel& source) {
  return add_layer(md, source, "seeds", MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR, [&](CMeshO& cm) {
    auto label = Allocator::GetPerVertexAttribute<float>(cm, kLabelAttribute);
    auto kind = Allocator::GetPerVertexAttribute<float>(cm, kSeedKindAttribute);
    auto radius = Allocator::GetPerVertexAttribute<float>(cm, kRadiusAttribute);
    auto v = Allocator::AddVertices(cm, seeds.size());
    for (const Seed& seed : seeds) {
      v->P() = to_coord(seed.position);
      v->Q() = float(seed.radius);
      v->C() = label_colour(seed.region);
      label[v] = float(seed.region);
      kind[v] = float(static_cast<int>(seed.kind));
      radius[v] = float(seed.radius);
      ++v;
    }
  });
}

ResultLayers add_result_layers(MeshDocument& md, const MeshResult& result, Stage stage, const MeshModel& source) {
  ResultLayers added;
  try {
    if (stage == Stage::Balls) {
      added.balls = add_balls_layer(md, result.balls, source);
    } else {
      added.surface = add_surface_layer(md, result.surface, source);
      added.seeds = add_seeds_layer(md, result.seeds, source);
      md.setCurrent(added.surface);
    }
  } catch (...) {
    for (MeshModel* layer : {added.balls, added.surface, added.seeds}) {
      if (layer) md.delMesh(layer);
    }
    throw;
  }
  return added;
}

}  // namespace vorocrust::meshlab
