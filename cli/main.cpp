// `vorocrust`: the command-line front end of libvorocrust.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "cells_command.hpp"
#include "check_balls_command.hpp"
#include "commands.hpp"
#include "mesh2d_command.hpp"
#include "exit_codes.hpp"
#include "quality_command.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/version.hpp"

namespace {

using namespace vorocrust;
using namespace vorocrust::cli;

constexpr const char* kVolumeFormatsHelp =
    "Volume mesh outputs, comma-separated: vtu (mesh.vtu), openfoam (case/), tough (MESH), pflotran (pflotran/: "
    "mesh.uge, a cell list per material, boundary connections per patch); default: all";

int report_error(const Error& e) {
  std::fprintf(stderr, "vorocrust: %s: %s\n", to_string(e.kind()),
               spelled_message(e.what(), e.where().option, Spelling::Cli).c_str());
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
  mesh.options.add(*mesh_cmd);
  mesh_cmd->add_flag("-q,--quiet", mesh.quiet, "Print nothing but errors");

  CompareArgs compare;
  CLI::App* compare_cmd = app.add_subcommand(
      "compare", "Mesh the input with VoroCrust and with clipped cells at one sizing and set them side by side: "
                 "boundary faces' edges, angles, faces per cell, non-convex cells, faces off their seed links, "
                 "volume error, time; OUTDIR/compare.json and compare.svg, each mesh in OUTDIR/vorocrust and "
                 "OUTDIR/clipped");
  compare_cmd->add_option("INPUT", compare.inputs, "Input meshes (.off .obj .stl .ply); several merge into one model")
      ->required();
  compare_cmd->add_option("-o,--output", compare.output_dir, "Output folder (created if missing)")->required();
  compare.options.add(*compare_cmd);
  compare_cmd->add_flag("-q,--quiet", compare.quiet, "Print nothing but errors and the table");

  Mesh2dArgs mesh2d;
  CLI::App* mesh2d_cmd = add_mesh2d_command(app, mesh2d);

  bool options_json_wanted = false;
  CLI::App* options_cmd = app.add_subcommand(
      "options", "List the options of `mesh` (the library's one table of them): name, default, range; with "
                 "--json the whole table, as every front end is made from it");
  options_cmd->add_flag("--json", options_json_wanted, "Print the table as one JSON list");

  CheckBallsArgs check;
  CLI::App* check_cmd =
      app.add_subcommand("check-balls", "Check a set of balls (balls.csv) against the ball conditions, independently");
  check_cmd->add_option("FILES", check.files,
                        "Input meshes (.off .obj .stl .ply), then the balls CSV last: model.obj balls.csv")
      ->required()
      ->expected(2, CLI::detail::expected_max_vector_size);
  check_cmd->add_flag("--smooth", check.smooth,
                      "Balls of a mesh --smooth run: the sharp angle defaults to that run's (60); check them "
                      "against the smoothed_surface.ply it wrote");
  check_cmd->add_option_function<double>(
      "--sharp-angle", [&](double degrees) { check.sharp_angle_degrees = degrees; },
      "Normal deviation in degrees (0,90) above which an edge is sharp; use the mesh's value (default 30, or 60 "
      "with --smooth)");
  check_cmd->add_option("--lipschitz", check.lipschitz, "L in (0,1) for condition C3; use the mesh's value")
      ->capture_default_str();
  check_cmd->add_option("--samples", check.face_samples, "Random sample points on faces, proportional to area")
      ->capture_default_str();
  check_cmd->add_option("--crease-samples", check.crease_samples,
                        "Random sample points on sharp edges, proportional to length")
      ->capture_default_str();
  check_cmd->add_option("--seed", check.seed, "Seed of the random samples")->capture_default_str();
  check_cmd->add_flag("--json", check.json, "Print one JSON object instead of text");
  add_domain_options(*check_cmd, check.domain);

  QualityArgs quality;
  CLI::App* quality_cmd = app.add_subcommand(
      "quality", "Measure a run's output surface (OUTDIR/surface.ply) against its input: angles, triangle quality, "
                 "Hausdorff distance, topology; and the cells of its seeds (OUTDIR/seeds.csv): aspect ratio, volume, "
                 "faces, shortest edge; draws OUTDIR/quality.svg");
  quality_cmd->add_option("OUTDIR", quality.output_dir, "Output folder of `vorocrust mesh`")->required();
  quality_cmd->add_option("--input", quality.inputs,
                          "Input meshes to compare with (default: the inputs named in OUTDIR/report.json)");
  quality_cmd->add_option("--samples", quality.options.random_samples,
                          "Random points per surface for the Hausdorff distance, on top of vertices and edge midpoints")
      ->capture_default_str();
  quality_cmd->add_option("--seed", quality.options.seed, "Seed of the random points")->capture_default_str();
  add_domain_options(*quality_cmd, quality.domain);
  quality_cmd->add_flag("--json", quality.json, "Print one JSON object instead of text");

  CellsArgs cells;
  cells.command_line.assign(argv, argv + argc);
  CLI::App* cells_cmd = app.add_subcommand(
      "cells", "Build the conforming Voronoi mesh of a seed set (a run's seeds.csv): mesh.vtu and an OpenFOAM case, "
               "its cell quality in report.json and quality.svg");
  cells_cmd->add_option("SEEDS", cells.seeds_file, "Seeds as written by `vorocrust mesh`: x,y,z,label,radius,kind")
      ->required();
  cells_cmd->add_option("-o,--output", cells.output_dir, "Output folder (created if missing)")->required();
  cells_cmd->add_option("--format", cells.formats, kVolumeFormatsHelp)
      ->delimiter(',')
      ->check(CLI::IsMember(volume_format_names()))
      ->capture_default_str();
  cells_cmd->add_option("--materials", cells.materials,
                        "Labels that get cells, comma-separated (default: every label > 0; 0 is outside)")
      ->delimiter(',');
  cells_cmd->add_option("--threads", cells.threads, "Worker threads, 0 for all cores")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cells_cmd->add_flag("-q,--quiet", cells.quiet, "Print nothing but errors");

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
    if (*options_cmd) return run_options(options_json_wanted);
    if (*check_cmd) return run_check_balls(check);
    if (*quality_cmd) return run_quality(quality);
    if (*cells_cmd) return run_cells(cells);
    if (*compare_cmd) {
      compare.command_line.assign(argv, argv + argc);
      return run_compare(compare);
    }
    if (*mesh2d_cmd) {
      mesh2d.command_line.assign(argv, argv + argc);
      return run_mesh2d(mesh2d);
    }
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
