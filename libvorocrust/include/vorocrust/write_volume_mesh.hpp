// vorocrust/write_volume_mesh.hpp — the volume mesh in the formats every front end offers.
//
// A format has a name (what `--format`, the Python module, the MeshLab filter and the FreeCAD
// workbench call it) and the file or folder it fills in an output folder:
//   vtu       mesh.vtu   write_vtu          (VTK, ParaView)
//   openfoam  case/      write_openfoam_case (checkMesh, the OpenFOAM solvers)
//   tough     MESH       write_tough_mesh   (TOUGH2, TOUGH3, TOUGHREACT)
//   pflotran  pflotran/  write_pflotran     (PFLOTRAN's explicit unstructured grid, regions)
//
// write_volume_mesh(mesh, folder, formats) writes the named formats into `folder` and removes
// what an earlier run left there under the others' names, so that no file passes for this
// run's. Throws Error(Usage) naming an unknown format, before writing anything; Error(Output)
// from the writers.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "vorocrust/cell_quality.hpp"
#include "vorocrust/cells.hpp"

namespace vorocrust {

struct VolumeFormat {
  const char* name;    // "vtu"
  const char* output;  // "mesh.vtu": a file, or a folder for "case" and "pflotran"
};

std::span<const VolumeFormat> volume_formats();

// Every format's name, in the order above: the default of every front end.
std::vector<std::string> volume_format_names();

// `quality`: the mesh's measure_cell_quality where the caller has it (write_vtu measures it
// otherwise).
void write_volume_mesh(const VoronoiMesh& mesh, const std::filesystem::path& folder,
                       const std::vector<std::string>& formats, const CellQuality* quality = nullptr);

// One format, by name, into its file or folder in `folder`; leaves the others' outputs alone.
// Throws Error(Usage) naming an unknown format.
void write_volume_format(const VoronoiMesh& mesh, const std::filesystem::path& folder, const std::string& format,
                         const CellQuality* quality = nullptr);

// Removes every volume format's output from `folder` (a run that made no cells).
void remove_volume_outputs(const std::filesystem::path& folder);

}  // namespace vorocrust
