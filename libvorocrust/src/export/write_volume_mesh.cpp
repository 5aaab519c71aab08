#include "vorocrust/write_volume_mesh.hpp"

#include <algorithm>
#include <array>

#include "vorocrust/error.hpp"
#include "vorocrust/write_openfoam.hpp"
#include "vorocrust/write_pflotran.hpp"
#include "vorocrust/write_tough.hpp"
#include "vorocrust/write_vtu.hpp"

namespace vorocrust {

namespace {

constexpr std::array<VolumeFormat, 4> kFormats = {{
    {"vtu", "mesh.vtu"},
    {"openfoam", "case"},
    {"tough", "MESH"},
    {"pflotran", "pflotran"},
}};

const VolumeFormat& format_named(const std::string& name) {
  for (const VolumeFormat& f : kFormats) {
    if (name == f.name) return f;
  }
  throw Error(Error::Kind::Usage, "unknown volume format '" + name + "': expected vtu, openfoam, tough or pflotran");
}

}  // namespace

void write_volume_format(const VoronoiMesh& mesh, const std::filesystem::path& folder, const std::string& format,
                         const CellQuality* quality) {
  const VolumeFormat& f = format_named(format);
  const std::filesystem::path where = folder / f.output;
  if (format == "vtu") write_vtu(mesh, where, quality);
  else if (format == "openfoam") write_openfoam_case(mesh, where);
  else if (format == "tough") write_tough_mesh(mesh, where);
  else write_pflotran(mesh, where);
}

std::span<const VolumeFormat> volume_formats() { return kFormats; }

std::vector<std::string> volume_format_names() {
  std::vector<std::string> names;
  for (const VolumeFormat& f : kFormats) names.emplace_back(f.name);
  return names;
}

void write_volume_mesh(const VoronoiMesh& mesh, const std::filesystem::path& folder,
                       const std::vector<std::string>& formats, const CellQuality* quality) {
  for (const std::string& name : formats) format_named(name);
  for (const VolumeFormat& f : kFormats) {
    if (std::find(formats.begin(), formats.end(), f.name) != formats.end()) {
      write_volume_format(mesh, folder, f.name, quality);
    } else {
      std::error_code ignored;
      std::filesystem::remove_all(folder / f.output, ignored);
    }
  }
}

void remove_volume_outputs(const std::filesystem::path& folder) {
  for (const VolumeFormat& f : kFormats) {
    std::error_code ignored;
    std::filesystem::remove_all(folder / f.output, ignored);
  }
}

}  // namespace vorocrust
