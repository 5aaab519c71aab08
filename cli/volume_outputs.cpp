#include "volume_outputs.hpp"

#include <algorithm>

#include "vorocrust/write_volume_mesh.hpp"

namespace vorocrust::cli {

void print_volume_outputs(const std::filesystem::path& folder, const std::vector<std::string>& formats, std::FILE* to) {
  const char* prefix = to == stderr ? "vorocrust: " : "";
  for (const VolumeFormat& f : volume_formats()) {
    if (std::find(formats.begin(), formats.end(), f.name) == formats.end()) continue;
    const std::string where = (folder / f.output).string();
    const std::string name = f.name;
    if (name == "vtu") std::fprintf(to, "%swrote %s (open it in ParaView)\n", prefix, where.c_str());
    if (name == "openfoam") {
      std::fprintf(to, "%swrote %s/ (check it with: checkMesh -case %s)\n", prefix, where.c_str(), where.c_str());
    }
    if (name == "tough") std::fprintf(to, "%swrote %s (TOUGH's ELEME and CONNE blocks)\n", prefix, where.c_str());
    if (name == "pflotran") {
      std::fprintf(to, "%swrote %s/ (mesh.uge for GRID TYPE UNSTRUCTURED_EXPLICIT, a region file per material "
                   "and per boundary patch)\n", prefix, where.c_str());
    }
  }
}

}  // namespace vorocrust::cli
