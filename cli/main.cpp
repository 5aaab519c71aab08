// `vorocrust`: the command-line front end of libvorocrust.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "cells_command.hpp"
#include "check_balls_command.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "quality_command.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/version.hpp"

namespace {

using namespace vorocrust;
using namespace vorocrust::cli;

constexpr const char* kVolumeFormatsHelp =
    "Volume mesh outputs, comma-separated: vtu (mesh.vtu), openfoam (case/), tough (MESH), pflotran (pflotran/: "
    "mesh.uge, a cell list per material, boundary connections per patch)";

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
  mesh_cmd->add_flag("--smooth", mesh.options.smooth,
                     "The input approximates a smooth surface (a scan, a coarse tessellation of a curved shape): "
                     "it is smoothed as one patch (boundary and non-manifold edges stay) and its features are found "
                     "on the result, so the folds of its tessellation are not creases; the sharp angle defaults to "
                     "60, the smoothing to 6 rounds (the paper's settings for smooth models) and the smallest "
                     "triangle angle to 30");
  mesh_cmd->add_option_function<double>(
      "--sharp-angle", [&](double degrees) { mesh.options.sharp_angle_degrees = degrees; },
      "Normal deviation in degrees (0,90) above which an edge is a sharp crease, and the most normals may turn "
      "between co-smooth points; default 30, which keeps every crease of the shared CAD models (fandisk, joint, "
      "bracket, hinge), or 60 with --smooth");
  mesh_cmd->add_option("--max-size", mesh.options.max_size, "Largest allowed ball radius and cell size");
  mesh_cmd->add_option("--sizing", mesh.options.sizing_file,
                       "Sizing file: lines 'x y z size' ('#' comments); sizes are interpolated between the points")
      ->check(CLI::ExistingFile);
  mesh_cmd->add_option_function<int>(
      "--smoothing-iterations", [&](int rounds) { mesh.options.smoothing_iterations = rounds; },
      "Rounds of adaptive Loop subdivision inside smooth patches before refinement; default 0, or 6 with --smooth");
  mesh_cmd->add_option("--smoothing-tolerance", mesh.options.smoothing_tolerance,
                       "How far smoothing should move the surface at most, as a fraction of the input's "
                       "bounding-box diagonal (a target): faces around a vertex Loop's rules would move farther are "
                       "first split at their midpoints, at most twice; 0: Loop's rules alone")
      ->capture_default_str();
  mesh_cmd->add_option_function<double>(
      "--min-triangle-angle", [&](double degrees) { mesh.options.min_triangle_angle_degrees = degrees; },
      "Split surface triangles away from features with an angle below this (degrees, 0 to 30; 0: none) by "
      "shrinking the balls that cover their circumcentres; default 0, or 30 with --smooth");
  add_domain_options(*mesh_cmd, mesh.domain, /*refuse=*/true);
  mesh_cmd->add_option("--interior", mesh.interior,
                       "Interior seeds: 'random' (Poisson-disk, graded from the surface inward), 'lattice' "
                       "(cubic, hex-dominant cells), 'cvt' (random, then Lloyd iterations)")
      ->check(CLI::IsMember({"random", "lattice", "cvt"}))
      ->capture_default_str();
  mesh_cmd->add_option("--cvt-iterations", mesh.options.cvt_iterations, "Lloyd iterations of --interior cvt")
      ->capture_default_str();
  mesh_cmd->add_option("--max-aspect-ratio", mesh.options.max_aspect_ratio,
                       "Split cells whose aspect ratio (enclosing sphere over inscribed ball) exceeds this with a "
                       "seed at their centroid, for at most 2 rounds; 0: none, else at least 3")
      ->capture_default_str();
  mesh_cmd->add_option("--format", mesh.formats, kVolumeFormatsHelp)
      ->delimiter(',')
      ->check(CLI::IsMember(volume_format_names()))
      ->capture_default_str();
  mesh_cmd->add_option("--stop-after", mesh.stop_after, "Stop after a stage and write its output: 'balls' (balls.csv, balls.vtk) or 'surface' "
                       "(also seeds.csv, surface.obj, surface.ply)")
      ->check(CLI::IsMember({"balls", "surface"}));
  mesh_cmd->add_flag("-q,--quiet", mesh.quiet, "Print nothing but errors");

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
  add_domain_options(*check_cmd, check.domain, /*refuse=*/false);

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
  add_domain_options(*quality_cmd, quality.domain, /*refuse=*/false);
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
    if (*check_cmd) return run_check_balls(check);
    if (*quality_cmd) {
      quality.domain_given = quality_cmd->count("--box") + quality_cmd->count("--self-intersections") > 0;
      return run_quality(quality);
    }
    if (*cells_cmd) return run_cells(cells);
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
