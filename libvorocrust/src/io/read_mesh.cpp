#include "vorocrust/read_mesh.hpp"

#include <algorithm>
#include <cctype>

#include "io/byte_source.hpp"
#include "io/readers.hpp"
#include "vorocrust/merge_surfaces.hpp"

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
  std::vector<NamedSurface> parts;
  parts.reserve(paths.size());
  for (const auto& path : paths) parts.push_back({path.stem().string(), read_mesh(path)});
  return merge_surfaces(parts);
}

}  // namespace vorocrust
