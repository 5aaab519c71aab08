#include <cstdio>
#include <filesystem>
#include <optional>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "progress_display.hpp"
#include "vorocrust/vorocrust.hpp"

namespace vorocrust::cli {

int run_mesh(const MeshArgs& args) {
  args.options.check();
  std::error_code ec;
  std::filesystem::create_directories(args.output_dir, ec);
  if (ec || !std::filesystem::is_directory(args.output_dir)) {
    throw Error(Error::Kind::Output, "cannot create the output folder: " + (ec ? ec.message() : "not a folder"),
                {.file = args.output_dir});
  }
  const ThreadLimit threads(args.options.threads);
  ProgressDisplay progress(args.quiet);

  RunReport report;
  report.command = args.command_line;
  report.inputs = args.inputs;
  report.options = args.options;
  const std::filesystem::path report_path = std::filesystem::path(args.output_dir) / "report.json";
  // report.json is written whatever the outcome, so a failed run still says why.
  const auto finish = [&](const std::string& status, const std::string& message, int code) {
    progress.finish();
    report.timings = progress.timings();
    report.status = status;
    report.message = message;
    write_file_atomically(report_path, run_report_json(report) + "\n");
    return code;
  };

  std::optional<SurfaceMesh> mesh;
  std::optional<MeshInfo> info;
  std::optional<ValidationReport> validation;
  std::optional<MeshResult> result;
  try {
    progress.begin("reading");
    mesh = read_meshes({args.inputs.begin(), args.inputs.end()});
    progress.begin("validating");
    validation = validate(*mesh);
    info = mesh_info(*mesh);
    report.mesh = &*mesh;
    report.input = &*info;
    report.validation = &*validation;
    for (const Finding& f : validation->findings) {
      const bool overridden = f.code == "self-intersection" && args.allow_self_intersections;
      if (f.severity == Finding::Severity::Error && !overridden) {
        const std::string hint = f.code == "self-intersection" ? " (--allow-self-intersections to mesh anyway)" : "";
        throw Error(Error::Kind::InvalidGeometry, f.message + hint);
      }
      if (!args.quiet && f.severity != Finding::Severity::Note) {
        std::fprintf(stderr, "vorocrust: %s: %s\n", to_string(f.severity), f.message.c_str());
      }
    }
    // The stages after the refinement do not exist yet: run to the balls, write them, and then
    // say "not yet" unless the balls were all that was asked for.
    MeshOptions options = args.options;
    options.stop_after = Stage::Balls;
    result = generate_mesh(*mesh, options, progress.callback());
    report.result = &*result;
    progress.begin("writing");
    const std::filesystem::path out(args.output_dir);
    write_balls_csv(result->balls, out / "balls.csv");
    write_balls_vtk(result->balls, out / "balls.vtk");
    // The surface the balls cover, when smoothing changed it: `check-balls` verifies against it.
    // A file from an earlier run in the same folder must not pass for this run's.
    if (result->features.smoothing_iterations > 0) {
      write_mesh(result->surface, out / "smoothed_surface.ply");
    } else {
      std::error_code ignored;
      std::filesystem::remove(out / "smoothed_surface.ply", ignored);
    }
    progress.finish();
    if (!args.quiet) {
      const RefinementStats& r = result->refinement;
      std::fprintf(stderr, "vorocrust: %zu balls (%zu corner, %zu crease, %zu patch) in %s\n",
                   r.balls[0] + r.balls[1] + r.balls[2], r.balls[0], r.balls[1], r.balls[2], args.output_dir.c_str());
    }
    if (args.stop_after != "balls") {
      throw Error(Error::Kind::NotImplemented,
                  "not yet: surface seeds and cells (paper 2.4-2.5) are not implemented in this version; the "
                  "balls are in " + (out / "balls.csv").string() + " (--stop-after balls asks for no more)");
    }
    return finish("ok", "", kOk);
  } catch (const Error& e) {
    finish(to_string(e.kind()), e.what(), exit_code_for(e.kind()));
    throw;
  }
}

}  // namespace vorocrust::cli
