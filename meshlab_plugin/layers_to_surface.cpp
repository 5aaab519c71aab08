#include <common/meshmodel.h>

#include "layers_to_surface.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>

#include "vorocrust/error.hpp"

namespace vorocrust::meshlab {

namespace {

using Coordinates = std::array<double, 3>;

std::string layer_name(const MeshModel& layer) { return layer.label().toStdString(); }

std::string layer_source(const MeshModel& layer) {
  const QString path = layer.fullName();
  return path.isEmpty() ? layer_name(layer) : path.toStdString();
}

}  // namespace

SurfaceMesh surface_from_layers(const std::vector<const MeshModel*>& layers) {
  SurfaceMesh surface;
  // Vertices of the layers already converted, by exact coordinates: the first one wins.
  std::map<Coordinates, Index> earlier;
  for (const MeshModel* layer : layers) {
    const CMeshO& cm = layer->cm;
    const std::string name = layer_name(*layer);
    if (cm.fn == 0) {
      throw Error(Error::Kind::InvalidGeometry,
                  "layer \"" + name + "\" has no faces: VoroCrust meshes the volume a triangle surface bounds",
                  {.file = layer_source(*layer)});
    }

    // The model's index of each of the layer's vertices (by position in cm.vert).
    constexpr Index kNone = std::numeric_limits<Index>::max();
    std::vector<Index> index(cm.vert.size(), kNone);
    const std::size_t first_new = surface.vertices.size();
    for (std::size_t v = 0; v < cm.vert.size(); ++v) {
      if (cm.vert[v].IsD()) continue;
      const auto& p = cm.vert[v].cP();
      const Coordinates c{double(p[0]), double(p[1]), double(p[2])};
      if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2])) {
        throw Error(Error::Kind::InvalidGeometry,
                    "vertex " + std::to_string(v) + " of layer \"" + name + "\" has a NaN or infinite coordinate",
                    {.file = layer_source(*layer)});
      }
      if (const auto found = earlier.find(c); found != earlier.end()) {
        index[v] = found->second;
      } else {
        index[v] = static_cast<Index>(surface.vertices.size());
        surface.vertices.emplace_back(c[0], c[1], c[2]);
      }
    }
    for (std::size_t v = first_new; v < surface.vertices.size(); ++v) {
      const Point& p = surface.vertices[v];
      earlier.emplace(Coordinates{p.x(), p.y(), p.z()}, static_cast<Index>(v));
    }

    // One group per selection state that has faces, made on first use.
    std::optional<Index> group[2];
    const auto group_of = [&](bool selected) {
      if (!group[selected]) {
        group[selected] = static_cast<Index>(surface.groups.size());
        surface.groups.push_back({selected ? name + "/selected" : name, layer_source(*layer)});
      }
      return *group[selected];
    };
    for (std::size_t f = 0; f < cm.face.size(); ++f) {
      const CFaceO& face = cm.face[f];
      if (face.IsD()) continue;
      Triangle t{};
      for (int k = 0; k < 3; ++k) {
        t[k] = index[vcg::tri::Index(cm, face.cV(k))];
        if (t[k] == kNone) {
          throw Error(Error::Kind::InvalidGeometry,
                      "face " + std::to_string(f) + " of layer \"" + name + "\" uses a deleted vertex",
                      {.file = layer_source(*layer)});
        }
      }
      surface.add_triangle(t, group_of(face.IsS()));
    }
  }
  return surface;
}

}  // namespace vorocrust::meshlab
