// `vorocrust mesh2d`: a conforming Voronoi mesh of a 2D domain (paper 2.6).
#include "mesh2d_command.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>

#include "exit_codes.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/plane.hpp"

namespace vorocrust::cli {

CLI::App* add_mesh2d_command(CLI::App& app, Mesh2dArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "mesh2d", "Generate a conforming Voronoi mesh of a 2D domain: a planar straight-line graph (Triangle's .poly, "
                "or OBJ polylines), its regions labelled, breaklines inside them followed by cell edges");
  cmd->add_option("INPUT", args.input, "The domain: .poly (vertices, segments, holes, regional attributes) or .obj (l elements)")
      ->required();
  cmd->add_option("-o,--output", args.output_dir, "Output folder (created if missing); report.json goes there")->required();
  args.options.add(*cmd, plane_option_names());
  std::string formats_help = "Outputs, comma-separated:";
  for (const std::string& f : plane_format_names()) formats_help += " " + f;
  cmd->add_option("--format", args.formats, formats_help + "; default: all")
      ->delimiter(',')
      ->check(CLI::IsMember(plane_format_names()));
  cmd->add_option("--thickness", args.thickness,
                  "Thickness of the one-cell slab the OpenFOAM case, TOUGH, PFLOTRAN and Exodus outputs are made of")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_flag("-q,--quiet", args.quiet, "Print nothing but errors");
  cmd->footer(
      "The options are mesh's, read in the plane: the balls are circles and the surface is the segments; "
      "--sharp-angle is how far a polyline may turn at a point that is no corner (30 by default); a sizing "
      "file's lines may also be 'x y size'; the lattice is hexagonal.");
  return cmd;
}

int run_mesh2d(const Mesh2dArgs& args) {
  MeshOptions table;
  args.options.apply(table);
  table.check();
  PlaneJob job;
  job.input = args.input;
  job.output_dir = args.output_dir;
  job.formats = args.formats;
  job.thickness = args.thickness;
  job.command = args.command_line;
  job.options = plane_options(table);
  const PlaneJobResult result = run_plane_job(job);
  if (!args.quiet) {
    for (const std::string& line : result.summary) std::fprintf(stderr, "vorocrust: %s\n", line.c_str());
  }
  return kOk;
}

}  // namespace vorocrust::cli
