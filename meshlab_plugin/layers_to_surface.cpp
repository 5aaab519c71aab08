#include <common/meshmodel.h>

#include "layers_to_surface.hpp"

#include <string>

#include "vorocrust/merge_surfaces.hpp"
#include "vorocrust/vcg.hpp"

namespace vorocrust::meshlab {

SurfaceMesh surface_from_layers(const std::vector<const MeshModel*>& layers) {
  std::vector<NamedSurface> parts;
  std::vector<std::string> group_names;  // every part's, in order: merging renames them
  for (const MeshModel* layer : layers) {
    const std::string name = layer->label().toStdString();
    const QString path = layer->fullName();
    SurfaceMesh surface = from_vcg(layer->cm, name, path.isEmpty() ? name : path.toStdString(),
                                   /*split_selection=*/true, "layer \"" + name + "\"");
    for (const FaceGroup& g : surface.groups) group_names.push_back(g.name);
    parts.push_back({name, std::move(surface)});
  }
  // Layers merge as input files do: shared vertices, a face two closed layers share one
  // interface between their solids, each closed layer a material named after it.
  SurfaceMesh merged = merge_surfaces(parts);
  for (std::size_t g = 0; g < merged.groups.size(); ++g) merged.groups[g].name = group_names[g];
  return merged;
}

}  // namespace vorocrust::meshlab
