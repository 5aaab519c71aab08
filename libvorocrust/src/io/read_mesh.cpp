#include "vorocrust/read_mesh.hpp"

#include <algorithm>
#include <cctype>

#include "io/byte_source.hpp"
#include "io/readers.hpp"
#include "io/region_labels.hpp"
#include "io/vertex_welder.hpp"

namespace vorocrust {

MeshFormat format_from_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".off") return MeshFormat::Off;
  if (ext == ".obj") return MeshFormat::Obj;
  if (ext == ".stl") return MeshFormat::Stl;
  if (ext == ".ply") return MeshFormat::Ply;
  io::fail(Error::Kind::UnreadableInput, path.string(), 0,
           "unknown format " + (ext.empty() ? std::string("(no extension)") : io::quote(ext)) +
               ": expected .off, .obj, .stl or .ply");
}

SurfaceMesh read_mesh(const std::filesystem::path& path) {
  const MeshFormat format = format_from_extension(path);
  const std::string bytes = io::read_file_bytes(path);
  const std::string file = path.string();
  switch (format) {
    case MeshFormat::Off: return io::parse_off(bytes, file);
    case MeshFormat::Obj: return io::parse_obj(bytes, file);
    case MeshFormat::Stl: return io::parse_stl(bytes, file);
    case MeshFormat::Ply: return io::parse_ply(bytes, file);
  }
  throw Error(Error::Kind::Internal, "unhandled mesh format");
}

SurfaceMesh read_meshes(const std::vector<std::filesystem::path>& paths) {
  if (paths.empty()) throw Error(Error::Kind::Usage, "no input file given");
  if (paths.size() == 1) return read_mesh(paths.front());

  SurfaceMesh merged;
  io::VertexWelder welder(merged.vertices);
  for (const auto& path : paths) {
    const SurfaceMesh part = read_mesh(path);
    const std::string stem = path.stem().string();
    const Index group_base = static_cast<Index>(merged.groups.size());
    for (const FaceGroup& g : part.groups) {
      merged.groups.push_back({part.groups.size() == 1 ? stem : stem + "/" + g.name, g.source_file});
    }
    // Shared with earlier files only: duplicates within one file stay as that file has them.
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
