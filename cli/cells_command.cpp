#include "cells_command.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "exit_codes.hpp"
#include "vorocrust/vorocrust.hpp"

namespace vorocrust::cli {

namespace fs = std::filesystem;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int run_cells(const CellsArgs& args) {
  auto start = std::chrono::steady_clock::now();
  const std::vector<Seed> seeds = read_seeds_csv(args.seeds_file);
  CellsOptions options;
  options.materials = args.materials;
  options.threads = args.threads;
  VoronoiMesh mesh = compute_cells(seeds, options);
  mesh.region_names = run_report_regions(fs::path(args.seeds_file).parent_path() / "report.json");
  const double cells_seconds = seconds_since(start);
  start = std::chrono::steady_clock::now();
  CellQualityOptions quality_options;
  quality_options.threads = args.threads;
  const CellQuality quality = measure_cell_quality(mesh, quality_options);
  const double quality_seconds = seconds_since(start);

  std::error_code ec;
  fs::create_directories(args.output_dir, ec);
  if (ec || !fs::is_directory(args.output_dir)) {
    throw Error(Error::Kind::Output, "cannot create the output folder: " + (ec ? ec.message() : "not a folder"),
                {.file = args.output_dir});
  }
  const fs::path out(args.output_dir);
  // The seeds go along (unless they are read from there), so that the folder holds the mesh in
  // its compact form and `vorocrust quality OUTDIR` finds them.
  std::error_code same_ec;
  if (!fs::equivalent(args.seeds_file, out / "seeds.csv", same_ec)) write_seeds_csv(seeds, out / "seeds.csv");
  write_volume_mesh(mesh, out, args.formats, &quality);
  write_histogram_svg(out / "quality.svg", "cell quality: " + args.seeds_file, {cell_quality_panel(quality)});
  CellsReport report;
  report.command = args.command_line;
  report.seeds_file = args.seeds_file;
  report.seeds = seeds.size();
  report.mesh = &mesh;
  report.quality = &quality;
  report.timings = {{"cells", cells_seconds}, {"cell quality", quality_seconds}};
  if (std::ifstream previous(out / "report.json", std::ios::binary); previous) {
    report.previous.assign(std::istreambuf_iterator<char>(previous), std::istreambuf_iterator<char>());
  }
  write_file_atomically(out / "report.json", cells_report_json(report) + "\n");

  if (!args.quiet) {
    const std::size_t interior = count_interior_faces(mesh);
    std::printf("%zu seeds: %zu cells, %zu faces (%zu interior, %zu boundary), %zu points, volume %.10g, in %.3f s\n",
                seeds.size(), mesh.cells.size(), mesh.faces.size(), interior, mesh.faces.size() - interior,
                mesh.points.size(), quality.total_volume, cells_seconds);
    std::printf("aspect ratio %.4g min, %.4g mean, %.4g max (cell %zu, seed %u); %zu cells above %.4g; in %.3f s\n",
                quality.min_aspect_ratio, quality.mean_aspect_ratio, quality.max_aspect_ratio, quality.worst_cell,
                quality.worst_seed, quality.aspect_ratio_above_high, quality.histogram_high, quality_seconds);
    std::printf("%s\n", face_figures_line(quality).c_str());
    std::vector<OutputFormat> formats;
    for (const std::string& name : args.formats) formats.push_back(*parse_output_format(name));
    for (const std::string& line : written_lines(out, formats)) std::printf("%s\n", line.c_str());
    std::printf("wrote %s, %s and %s\n", (out / "seeds.csv").c_str(), (out / "report.json").c_str(),
                (out / "quality.svg").c_str());
  }
  return kOk;
}

}  // namespace vorocrust::cli
