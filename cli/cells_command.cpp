#include "cells_command.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "exit_codes.hpp"
#include "vorocrust/vorocrust.hpp"

namespace vorocrust::cli {

namespace fs = std::filesystem;

int run_cells(const CellsArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Seed> seeds = read_seeds_csv(args.seeds_file);
  CellsOptions options;
  options.materials = args.materials;
  options.threads = args.threads;
  const VoronoiMesh mesh = compute_cells(seeds, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::error_code ec;
  fs::create_directories(args.output_dir, ec);
  if (ec || !fs::is_directory(args.output_dir)) {
    throw Error(Error::Kind::Output, "cannot create the output folder: " + (ec ? ec.message() : "not a folder"),
                {.file = args.output_dir});
  }
  const fs::path out(args.output_dir);
  const auto wants = [&](const char* format) {
    return std::find(args.formats.begin(), args.formats.end(), format) != args.formats.end();
  };
  if (wants("vtu")) write_vtu(mesh, out / "mesh.vtu");
  if (wants("openfoam")) write_openfoam_case(mesh, out / "case");

  if (!args.quiet) {
    const std::size_t interior = count_interior_faces(mesh);
    std::printf("%zu seeds: %zu cells, %zu faces (%zu interior, %zu boundary), %zu points, volume %.10g, in %.3f s\n",
                seeds.size(), mesh.cells.size(), mesh.faces.size(), interior, mesh.faces.size() - interior,
                mesh.points.size(), total_volume(mesh), seconds);
    if (wants("vtu")) std::printf("wrote %s\n", (out / "mesh.vtu").c_str());
    if (wants("openfoam")) std::printf("wrote %s/ (check it with: checkMesh -case %s)\n", (out / "case").c_str(), (out / "case").c_str());
  }
  return kOk;
}

}  // namespace vorocrust::cli
