// vorocrust/write_volume_mesh.hpp — the volume mesh in the formats every front end offers.
//
// The volume formats are the entries of output_formats() (outputs.hpp) marked `volume`: a name
// (what `--format`, the Python module, the MeshLab filter and the FreeCAD workbench call it) and
// the file or folder it fills in an output folder:
//   vtu       mesh.vtu   write_vtu           (VTK, ParaView)
//   openfoam  case/      write_openfoam_case (checkMesh, the OpenFOAM solvers)
//   tough     MESH       write_tough_mesh    (TOUGH2, TOUGH3, TOUGHREACT)
//   pflotran  pflotran/  write_pflotran      (PFLOTRAN's explicit unstructured grid, regions)
//
// write_volume_mesh(mesh, folder, formats) writes the named formats into `folder` and removes
// what an earlier run left there under the others' names, so that no file passes for this
// run's. Throws Error(Usage) naming an unknown format, before writing anything; Error(Output)
// from the writers.
#pragma once

#include "vorocrust/api.hpp"

#include <filesystem>
#include <string_view>
#include <string>
#include <vector>

#include "vorocrust/cell_quality.hpp"
#include "vorocrust/cells.hpp"

namespace vorocrust {

// Every volume format's name, in the table's order: the default of `vorocrust cells`.
VOROCRUST_API std::vector<std::string> volume_format_names();

// `quality`: the mesh's measure_cell_quality where the caller has it (write_vtu measures it
// otherwise).
VOROCRUST_API void write_volume_mesh(const VoronoiMesh& mesh, const std::filesystem::path& folder,
                                     const std::vector<std::string>& formats, const CellQuality* quality = nullptr);

// One format, by name, into its file or folder in `folder`; leaves the others' outputs alone.
// Throws Error(Usage) naming an unknown format.
VOROCRUST_API void write_volume_format(const VoronoiMesh& mesh, const std::filesystem::path& folder,
                                       std::string_view format, const CellQuality* quality = nullptr);

}  // namespace vorocrust
