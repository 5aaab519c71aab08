#include <common/meshmodel.h>

#include "layers_to_surface.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>

#include "vorocrust/error.hpp"
#include "vorocrust/merge_surfaces.hpp"

namespace vorocrust::meshlab {

namespace {

std::string layer_name(const MeshModel& layer) { return layer.label().toStdString(); }

std::string layer_source(const MeshModel& layer) {
  const QString path = layer.fullName();
  return path.isEmpty() ? layer_name(layer) : path.toStdString();
}

}  // namespace

SurfaceMesh surface_from_layers(const std::vector<const MeshModel*>& layers) {
  std::vector<NamedSurface> parts;
  std::vector<std::string> group_names;  // every part's, in order: merging renames them
  for (const MeshModel* layer : layers) {
    const CMeshO& cm = layer->cm;
    const std::string name = layer_name(*layer);
    if (cm.fn == 0) {
      throw Error(Error::Kind::InvalidGeometry,
                  "layer \"" + name + "\" has no faces: VoroCrust meshes the volume a triangle surface bounds",
                  {.file = layer_source(*layer)});
    }
    SurfaceMesh surface;
    // The layer's index of each of its vertices (by position in cm.vert).
    constexpr Index kNone = std::numeric_limits<Index>::max();
    std::vector<Index> index(cm.vert.size(), kNone);
    for (std::size_t v = 0; v < cm.vert.size(); ++v) {
      if (cm.vert[v].IsD()) continue;
      const auto& p = cm.vert[v].cP();
      const Point c{static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2])};
      if (!c.allFinite()) {
        throw Error(Error::Kind::InvalidGeometry,
                    "vertex " + std::to_string(v) + " of layer \"" + name + "\" has a NaN or infinite coordinate",
                    {.file = layer_source(*layer)});
      }
      index[v] = static_cast<Index>(surface.vertices.size());
      surface.vertices.push_back(c);
    }

    // One group per selection state that has faces, made on first use.
    std::optional<Index> group[2];
    const auto group_of = [&](bool selected) {
      if (!group[selected]) {
        group[selected] = static_cast<Index>(surface.groups.size());
        surface.groups.push_back({selected ? name + "/selected" : name, layer_source(*layer)});
        group_names.push_back(surface.groups.back().name);
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
    parts.push_back({name, std::move(surface)});
  }
  // Layers merge as input files do: shared vertices, a face two closed layers share one
  // interface between their solids, each closed layer a material named after it.
  SurfaceMesh merged = merge_surfaces(parts);
  for (std::size_t g = 0; g < merged.groups.size(); ++g) merged.groups[g].name = group_names[g];
  return merged;
}

}  // namespace vorocrust::meshlab
