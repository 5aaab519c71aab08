#include "vorocrust/write_volume_mesh.hpp"

#include "core/memory.hpp"

#include <algorithm>

#include "vorocrust/error.hpp"
#include "vorocrust/exodus.hpp"
#include "vorocrust/outputs.hpp"
#include "vorocrust/write_openfoam.hpp"
#include "vorocrust/write_pflotran.hpp"
#include "vorocrust/write_tough.hpp"
#include "vorocrust/write_vtu.hpp"

namespace vorocrust {

namespace {

const OutputFormatSpec& volume_format_named(std::string_view name) {
  const std::optional<OutputFormat> format = parse_output_format(name);
  if (!format || !output_format(*format).volume) {
    std::string known;
    for (const std::string& n : volume_format_names()) known += (known.empty() ? "" : ", ") + n;
    throw Error(Error::Kind::Usage, "unknown volume format '" + std::string(name) + "': expected " + known);
  }
  return output_format(*format);
}

}  // namespace

void write_volume_format(const VoronoiMesh& mesh, const std::filesystem::path& folder, std::string_view format,
                         const CellQuality* quality) {
  const OutputFormatSpec& f = volume_format_named(format);
  const std::filesystem::path where = folder / std::string(f.files[0]);
  switch (f.format) {
    case OutputFormat::Vtu: write_vtu(mesh, where, quality); break;
    case OutputFormat::OpenFoam: write_openfoam_case(mesh, where); break;
    case OutputFormat::Tough: write_tough_mesh(mesh, where); break;
    case OutputFormat::Pflotran: write_pflotran(mesh, where); break;
    case OutputFormat::Exodus: write_exodus(mesh, where); break;
    default: break;
  }
  // Each writer builds its file's arrays or text beside the mesh; the next starts from the mesh alone.
  release_free_memory();
}

std::vector<std::string> volume_format_names() {
  std::vector<std::string> names;
  for (const OutputFormatSpec& f : output_formats()) {
    if (f.volume) names.emplace_back(f.name);
  }
  return names;
}

void write_volume_mesh(const VoronoiMesh& mesh, const std::filesystem::path& folder,
                       const std::vector<std::string>& formats, const CellQuality* quality) {
  for (const std::string& name : formats) volume_format_named(name);
  for (const OutputFormatSpec& f : output_formats()) {
    if (!f.volume) continue;
    if (std::find(formats.begin(), formats.end(), f.name) != formats.end()) {
      write_volume_format(mesh, folder, f.name, quality);
    } else {
      std::error_code ignored;
      std::filesystem::remove_all(folder / std::string(f.files[0]), ignored);
    }
  }
}

}  // namespace vorocrust
