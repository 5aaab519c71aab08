#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "cell_figures.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "progress_display.hpp"
#include "volume_outputs.hpp"
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
  MeshOptions options = args.options;
  options.stop_after = args.stop_after == "balls"     ? Stage::Balls
                       : args.stop_after == "surface" ? Stage::Surface
                                                      : Stage::Cells;
  options.interior = args.interior == "lattice" ? InteriorMode::Lattice
                     : args.interior == "cvt"   ? InteriorMode::Cvt
                                                : InteriorMode::Random;
  args.domain.apply(options);
  report.options = options;
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
    validation = validate(*mesh, {.self_intersections_are_errors = options.self_intersections == SelfIntersections::Refuse});
    info = mesh_info(*mesh);
    report.mesh = &*mesh;
    report.input = &*info;
    report.validation = &*validation;
    for (const Finding& f : validation->findings) {
      if (f.severity == Finding::Severity::Error) {
        const std::string hint =
            f.code == "self-intersection" ? " (--self-intersections resolve cuts them along their intersection curves)" : "";
        throw Error(Error::Kind::InvalidGeometry, f.message + hint);
      }
      if (!args.quiet && f.severity != Finding::Severity::Note) {
        std::fprintf(stderr, "vorocrust: %s: %s\n", to_string(f.severity), f.message.c_str());
      }
    }
    result = generate_mesh(*mesh, options, progress.callback());
    report.result = &*result;
    progress.begin("writing");
    const std::filesystem::path out(args.output_dir);
    // A file from an earlier run in the same folder must not pass for this run's.
    const auto write_or_remove = [&](bool made, const char* name, const auto& write) {
      if (made) {
        write(out / name);
      } else {
        std::error_code ignored;
        std::filesystem::remove(out / name, ignored);
      }
    };
    write_balls_csv(result->balls, out / "balls.csv");
    write_balls_vtk(result->balls, out / "balls.vtk");
    // The surface the balls cover, when smoothing changed it: `check-balls` verifies against it.
    write_or_remove(result->features.smoothing_iterations > 0, "smoothed_surface.ply",
                    [&](const auto& path) { write_mesh(result->smoothed_input, path); });
    const bool surface = options.stop_after >= Stage::Surface;
    write_or_remove(surface, "seeds.csv", [&](const auto& path) { write_seeds_csv(result->seeds, path); });
    write_or_remove(surface, "surface.obj", [&](const auto& path) { write_mesh(result->surface, path); });
    write_or_remove(surface, "surface.ply", [&](const auto& path) { write_mesh(result->surface, path); });
    const bool cells = options.stop_after >= Stage::Cells;
    if (cells) {
      write_volume_mesh(result->cells, out, args.formats, result->cell_quality ? &*result->cell_quality : nullptr);
    } else {
      remove_volume_outputs(out);
    }
    write_or_remove(surface, "quality.svg", [&](const auto& path) {
      std::vector<HistogramPanel> panels = {surface_quality_panel(*result->surface_quality)};
      if (result->cell_quality) panels.push_back(cell_quality_panel(*result->cell_quality));
      write_histogram_svg(path, "quality: " + (out / "surface.ply").string(), panels);
    });
    progress.finish();
    if (!args.quiet) {
      const SelfIntersectionStats& s = result->self_intersections;
      if (s.faces_cut > 0) {
        std::fprintf(stderr, "vorocrust: self-intersections resolved: %zu faces cut along their intersection curves "
                     "(%zu new points), %zu faces left inside one region dropped, %zu faces in all\n",
                     s.faces_cut, s.points_added, s.faces_dropped, s.faces);
      }
      const FeatureCounts& f = result->features;
      if (f.smoothing_rounds_refused > 0 || f.smoothing_rounds_crossing > 0) {
        std::string why;
        if (f.smoothing_rounds_refused > 0) {
          why += "; " + std::to_string(f.smoothing_rounds_refused) + " would make a sharp feature the input lacks";
        }
        if (f.smoothing_rounds_crossing > 0) {
          why += "; " + std::to_string(f.smoothing_rounds_crossing) + " would carry the surface through itself";
        }
        std::fprintf(stderr, "vorocrust: smoothing kept %d round(s)%s\n", f.smoothing_iterations, why.c_str());
      }
      const RefinementStats& r = result->refinement;
      std::fprintf(stderr, "vorocrust: %zu balls (%zu corner, %zu crease, %zu patch) in %s\n",
                   r.balls[0] + r.balls[1] + r.balls[2], r.balls[0], r.balls[1], r.balls[2], args.output_dir.c_str());
      if (surface) {
        const std::size_t splits = result->slivers.rounds_for(SliverIteration::Shrunk::ForSkinnyTriangles);
        std::fprintf(stderr, "vorocrust: %zu surface seeds, a surface of %zu triangles after %zu rounds of sliver "
                     "elimination%s\n", static_cast<std::size_t>(std::count_if(result->seeds.begin(), result->seeds.end(),
                                                  [](const Seed& s) { return s.kind == SeedKind::Surface; })),
                     result->surface.num_faces(),
                     result->slivers.rounds_for(SliverIteration::Shrunk::ForSlivers),
                     splits > 0 ? (" and " + std::to_string(splits) + " of splitting skinny triangles").c_str() : "");
        const SurfaceQuality& q = *result->surface_quality;
        std::fprintf(stderr, "vorocrust: smallest angle %.1f deg, %.2f %% of angles below 30 deg, Q min %.3f, "
                     "Hausdorff %.3f %% of the diagonal, topology %s\n", q.min_angle_degrees,
                     q.percent_angles_below_30, q.min_quality, 100 * q.hausdorff_relative,
                     q.topology_matches ? "as the input's" : "DIFFERS from the input's");
      }
    }
    if (cells && !args.quiet) {
      const InteriorStats& i = result->interior;
      std::fprintf(stderr, "vorocrust: %zu interior and %zu outside seeds (%s); %zu cells, %zu faces (%zu between "
                   "cells), volume %.10g\n", i.interior_seeds, i.outside_seeds, args.interior.c_str(),
                   result->cells.cells.size(), result->cells.faces.size(), count_interior_faces(result->cells),
                   total_volume(result->cells));
      const CellQuality& q = *result->cell_quality;
      std::fprintf(stderr, "vorocrust: cell aspect ratio %.3g mean, %.3g max (seed %u); %zu cells above %.3g\n",
                   q.mean_aspect_ratio, q.max_aspect_ratio, q.worst_seed, q.aspect_ratio_above_high, q.histogram_high);
      print_face_figures(q, stderr);
      print_volume_outputs(out, args.formats);
    }
    return finish("ok", "", kOk);
  } catch (const Error& e) {
    finish(to_string(e.kind()), e.what(), exit_code_for(e.kind()));
    throw;
  }
}

}  // namespace vorocrust::cli
