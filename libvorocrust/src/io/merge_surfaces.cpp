#include "vorocrust/merge_surfaces.hpp"

#include "io/region_labels.hpp"
#include "io/vertex_welder.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust {

SurfaceMesh merge_surfaces(std::span<const NamedSurface> parts) {
  if (parts.empty()) throw Error(Error::Kind::Usage, "no surface to merge");

  SurfaceMesh merged;
  io::VertexWelder welder(merged.vertices);
  for (const NamedSurface& named : parts) {
    const SurfaceMesh& part = named.mesh;
    const Index group_base = static_cast<Index>(merged.groups.size());
    for (const FaceGroup& g : part.groups) {
      merged.groups.push_back({part.groups.size() == 1 ? named.name : named.name + "/" + g.name, g.source_file});
    }
    // Shared with earlier parts only: duplicates within one part stay as that part has them.
    const std::size_t first_new = merged.vertices.size();
    std::vector<Index> vertex_map(part.vertices.size());
    for (std::size_t v = 0; v < part.vertices.size(); ++v) {
      vertex_map[v] = welder.find(part.vertices[v]);
      if (vertex_map[v] == io::VertexWelder::none) {
        vertex_map[v] = static_cast<Index>(merged.vertices.size());
        merged.vertices.push_back(part.vertices[v]);
      }
    }
    welder.index_from(first_new);
    if (part.has_regions() && !merged.has_regions()) merged.face_regions.assign(merged.triangles.size(), RegionPair{});
    for (std::size_t f = 0; f < part.triangles.size(); ++f) {
      const Triangle& t = part.triangles[f];
      merged.add_triangle({vertex_map[t[0]], vertex_map[t[1]], vertex_map[t[2]]}, group_base + part.face_group[f],
                          part.face_line[f]);
      if (part.has_regions()) {
        const RegionPair r = part.face_regions[f];
        merged.face_regions.back() = {
            r.back < 0 ? r.back : io::region_index(merged, part.region_names[r.back]),
            r.front < 0 ? r.front : io::region_index(merged, part.region_names[r.front])};
      }
    }
  }
  return merged;
}

}  // namespace vorocrust
