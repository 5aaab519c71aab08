#include "io/region_labels.hpp"

#include <algorithm>
#include <optional>

namespace vorocrust::io {

std::int32_t region_index(SurfaceMesh& mesh, const std::string& name) {
  const auto it = std::find(mesh.region_names.begin(), mesh.region_names.end(), name);
  if (it != mesh.region_names.end()) return static_cast<std::int32_t>(it - mesh.region_names.begin());
  mesh.region_names.push_back(name);
  return static_cast<std::int32_t>(mesh.region_names.size() - 1);
}

void assign_regions_from_group_names(SurfaceMesh& mesh) {
  std::vector<std::optional<RegionPair>> by_group(mesh.groups.size());
  bool any = false;
  for (std::size_t g = 0; g < mesh.groups.size(); ++g) {
    const std::string& name = mesh.groups[g].name;
    const std::size_t bar = name.find('|');
    if (bar == std::string::npos || bar == 0 || bar + 1 == name.size() || name.find('|', bar + 1) != std::string::npos) continue;
    by_group[g] = RegionPair{region_index(mesh, name.substr(0, bar)), region_index(mesh, name.substr(bar + 1))};
    any = true;
  }
  if (!any) return;
  mesh.face_regions.assign(mesh.triangles.size(), RegionPair{});
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (by_group[mesh.face_group[f]]) mesh.face_regions[f] = *by_group[mesh.face_group[f]];
  }
}

}  // namespace vorocrust::io
