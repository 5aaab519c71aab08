// vorocrust/write_mesh.hpp — writing a SurfaceMesh as OFF, OBJ (groups kept), STL or PLY.
//
// The format follows the extension; STL and PLY are written binary unless `ascii` is set.
// Files are written to a temporary name beside the target and renamed into place, so a
// failed write never leaves a half-written file. PLY faces carry `back_region`/`front_region`
// when the mesh has region labels, and OBJ groups named "BACK|FRONT" carry them the same way.
#pragma once

#include "vorocrust/api.hpp"

#include <filesystem>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

struct VOROCRUST_API WriteOptions {
  bool ascii = false;
};

VOROCRUST_API void write_mesh(const SurfaceMesh& mesh, const std::filesystem::path& path,
                const WriteOptions& options = {});

}  // namespace vorocrust
