// vorocrust/outputs.hpp — the files a mesh run can write, declared once.
//
// Contract: output_formats() lists every output in the order front ends show them; each has the
// name every front end uses for it (`--format vtu`, formats=["vtu"], the MeshLab filter's and the
// FreeCAD panel's check boxes), the files or folders it fills in an output folder, the stage a run
// must reach to have it, and a line of help. to_string/parse_output_format convert names.
// report.json is no format: a job with an output folder always writes it, whatever the outcome.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string_view>

#include "vorocrust/api.hpp"
#include "vorocrust/modes.hpp"

namespace vorocrust {

enum class OutputFormat {
  Vtu,         // mesh.vtu: VTK polyhedra (ParaView)
  OpenFoam,    // case/: an OpenFOAM polyMesh with zones
  Tough,       // MESH: TOUGH's ELEME and CONNE blocks
  Pflotran,    // pflotran/: PFLOTRAN's explicit unstructured grid
  Exodus,      // mesh.exo: Exodus II, a block per material, side sets per patch and interface
  Tets,        // tets.vtu: the tetrahedra dual to a clipped mesh (Yan et al.)
  Seeds,       // seeds.csv: the whole mesh in compact form
  SurfaceObj,  // surface.obj
  SurfacePly,  // surface.ply
  Balls,       // balls.csv, balls.vtk, and smoothed_surface.ply when smoothing changed the input
  QualitySvg,  // quality.svg: the histograms
  ReportHtml,  // report.html: the run's figures, tables and pictures, for a browser
};

struct VOROCRUST_API OutputFormatSpec {
  OutputFormat format;
  std::string_view name;                  // "vtu"
  std::span<const std::string_view> files;  // what it fills in the output folder: "mesh.vtu", "case"
  Stage needs;                            // the stage a run must reach to have it
  bool volume;                            // written from the cells (the volume mesh)
  std::string_view help;
};

template <>
struct ChoiceNames<OutputFormat> {
  static constexpr std::array<std::string_view, 12> names = {"vtu",  "openfoam", "tough", "pflotran",
                                                               "exodus", "tets", "seeds", "obj",
                                                               "ply", "balls", "svg", "html"};
};

VOROCRUST_API std::span<const OutputFormatSpec> output_formats() noexcept;
VOROCRUST_API const OutputFormatSpec& output_format(OutputFormat format) noexcept;
inline const char* to_string(OutputFormat format) noexcept { return choice_name(format).data(); }
inline std::optional<OutputFormat> parse_output_format(std::string_view name) noexcept {
  return parse_choice<OutputFormat>(name);
}

}  // namespace vorocrust
