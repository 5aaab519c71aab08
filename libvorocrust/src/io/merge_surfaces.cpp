#include "vorocrust/merge_surfaces.hpp"

#include <algorithm>
#include <map>

#include "core/edge_topology.hpp"
#include "core/face_components.hpp"
#include "io/region_labels.hpp"
#include "io/vertex_welder.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/validate.hpp"

namespace vorocrust {

namespace {

using CornerSet = std::array<Index, 3>;

CornerSet corner_set(Triangle t) {
  std::sort(t.begin(), t.end());
  return t;
}

// A part that is one closed manifold surface bounds a solid: turned outward, its faces have the
// solid behind them. Anything else (sheets, several shells, non-manifold parts) is left for the
// region stage to read from the geometry.
bool orient_as_solid(SurfaceMesh& part) {
  if (part.has_regions()) return false;
  const EdgeTopology topology = build_edge_topology(part);
  for (std::size_t e = 0; e < topology.num_edges(); ++e) {
    if (topology.valence(e) != 2) return false;
  }
  if (face_components(part, topology).faces.size() != 1) return false;
  ValidationOptions orient_only;
  orient_only.check_self_intersections = false;
  const ValidationReport report = validate(part, orient_only);
  return report.find("non-orientable") == nullptr;
}

}  // namespace

SurfaceMesh merge_surfaces(std::span<const NamedSurface> parts) {
  if (parts.empty()) throw Error(Error::Kind::Usage, "no surface to merge");

  SurfaceMesh merged;
  // Labels of the merged faces, kept apart until the end: a part without labels may come first.
  std::vector<RegionPair> labels_of;
  bool labelled = false;
  io::VertexWelder welder(merged.vertices);
  std::map<CornerSet, Index> earlier_faces;  // faces of the parts merged so far
  for (const NamedSurface& named : parts) {
    SurfaceMesh part = named.mesh;
    const bool solid = parts.size() > 1 && orient_as_solid(part);
    if (solid) {
      part.region_names = {named.name};
      part.face_regions.assign(part.num_faces(), RegionPair{0, RegionPair::kUnknownRegion});
    }
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
    labelled = labelled || part.has_regions();
    const auto merged_label = [&](std::int32_t r) {
      return r < 0 ? r : io::region_index(merged, part.region_names[r]);
    };
    const std::size_t first_face = merged.num_faces();
    for (std::size_t f = 0; f < part.triangles.size(); ++f) {
      const Triangle& t = part.triangles[f];
      const Triangle mapped{vertex_map[t[0]], vertex_map[t[1]], vertex_map[t[2]]};
      const RegionPair labels = part.has_regions() ? RegionPair{merged_label(part.face_regions[f].back),
                                                                merged_label(part.face_regions[f].front)}
                                                   : RegionPair{};
      // A face an earlier part has too is one face between the two: it keeps the earlier copy,
      // which learns what this part says of its sides.
      const auto shared = earlier_faces.find(corner_set(mapped));
      if (shared != earlier_faces.end()) {
        const Index g = shared->second;
        if (part.has_regions()) {
          const bool reversed = edge_direction(merged.triangles[g], mapped[0], mapped[1]) < 0;
          RegionPair& known = labels_of[g];
          for (auto [mine, theirs] : {std::pair{labels.back, reversed ? &known.front : &known.back},
                                      std::pair{labels.front, reversed ? &known.back : &known.front}}) {
            if (mine < 0) continue;
            if (*theirs >= 0 && *theirs != mine) {
              throw Error(Error::Kind::InvalidGeometry,
                          describe_face(merged, g) + " of part " + merged.groups[merged.face_group[g]].name +
                              " is also face " + std::to_string(f) + " of part " + named.name + ", which puts " +
                              merged.region_names[mine] + " where the first puts " + merged.region_names[*theirs] +
                              ": solids may touch but not overlap",
                          {.face = g});
            }
            *theirs = mine;
          }
        }
        continue;
      }
      merged.add_triangle(mapped, group_base + part.face_group[f], part.face_line[f]);
      labels_of.push_back(labels);
    }
    for (std::size_t f = first_face; f < merged.num_faces(); ++f) {
      earlier_faces.emplace(corner_set(merged.triangles[f]), static_cast<Index>(f));
    }
  }
  if (labelled) merged.face_regions = std::move(labels_of);
  return merged;
}

}  // namespace vorocrust
