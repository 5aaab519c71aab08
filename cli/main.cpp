// `vorocrust`: the command-line front end of libvorocrust.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/version.hpp"

namespace {

using namespace vorocrust;
using namespace vorocrust::cli;

int report_error(const Error& e) {
  std::fprintf(stderr, "vorocrust: %s: %s\n", to_string(e.kind()), e.what());
  return exit_code_for(e.kind());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"vorocrust " VOROCRUST_VERSION ": conforming Voronoi meshing without clipping", "vorocrust"};
  app.footer(kExitCodeHelp);
  app.set_version_flag("--version", VOROCRUST_VERSION);
  app.require_subcommand(1);

  InfoArgs info;
  CLI::App* info_cmd = app.add_subcommand("info", "Read, validate and describe input surfaces");
  info_cmd->add_option("INPUT", info.inputs, "Input meshes (.off .obj .stl .ply); several merge into one model")
      ->required();
  info_cmd->add_flag("--json", info.json, "Print one JSON object instead of text");
  info_cmd->add_flag("--no-self-intersections", info.skip_self_intersections,
                     "Skip the self-intersection check (faster on huge inputs)");

  MeshArgs mesh;
  CLI::App* mesh_cmd = app.add_subcommand("mesh", "Generate a conforming Voronoi mesh of the input's volume");
  mesh_cmd->add_option("INPUT", mesh.inputs, "Input meshes (.off .obj .stl .ply); several merge into one model")
      ->required();
  mesh_cmd->add_option("-o,--output", mesh.output_dir, "Output folder (created if missing); report.json goes there")
      ->required();
  mesh_cmd->add_option("--seed", mesh.options.seed, "Random seed; equal seeds give equal meshes")
      ->capture_default_str();
  mesh_cmd->add_option("--threads", mesh.options.threads, "Worker threads, 0 for all cores")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  mesh_cmd->add_option("--lipschitz", mesh.options.lipschitz, "L in (0,1): how fast ball radii may vary")
      ->capture_default_str();
  mesh_cmd->add_option("--sharp-angle", mesh.options.sharp_angle_degrees,
                       "Dihedral deviation in degrees (0,90) above which an edge is a sharp crease")
      ->capture_default_str();
  mesh_cmd->add_option("--max-size", mesh.options.max_size, "Largest allowed ball radius and cell size");
  mesh_cmd->add_flag("--allow-self-intersections", mesh.allow_self_intersections,
                     "Mesh even when input faces intersect each other");
  mesh_cmd->add_flag("-q,--quiet", mesh.quiet, "Print nothing but errors");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "vorocrust: usage error: %s\nRun 'vorocrust --help' for the options.\n", e.what());
    return kUsage;
  }

  try {
    if (*info_cmd) return run_info(info);
    mesh.command_line.assign(argv, argv + argc);
    return run_mesh(mesh);
  } catch (const Error& e) {
    return report_error(e);
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "vorocrust: internal error: out of memory\n");
    return kInternalError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vorocrust: internal error: %s\n", e.what());
    return kInternalError;
  }
}
