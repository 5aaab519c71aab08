#include "quality_command.hpp"

#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <utility>

#include "exit_codes.hpp"
#include "vorocrust/vorocrust.hpp"

namespace vorocrust::cli {

namespace {

namespace fs = std::filesystem;

// The model files to compare against: those named, or those the run that made OUTDIR read.
std::vector<fs::path> input_paths(const QualityArgs& args, const fs::path& out) {
  if (!args.inputs.empty()) return {args.inputs.begin(), args.inputs.end()};
  const fs::path report = out / "report.json";
  if (!fs::exists(report)) {
    throw Error(Error::Kind::UnreadableInput,
                "missing, so the input model is unknown: name it with --input MODEL", {.file = report.string()});
  }
  std::vector<fs::path> paths;
  for (const std::string& name : run_report_inputs(report)) {
    if (!fs::exists(name)) {
      throw Error(Error::Kind::UnreadableInput,
                  "cannot open: no such file (named in " + report.string() +
                      "; a relative path there is relative to the folder the run started in: name the model with "
                      "--input MODEL)",
                  {.file = name});
    }
    paths.emplace_back(name);
  }
  return paths;
}

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

// "3 components: 2 closed with Euler characteristic 2, 1 open with Euler characteristic 1".
std::string describe(const SurfaceTopology& t) {
  std::map<std::pair<bool, long>, std::size_t> kinds;
  for (std::size_t c = 0; c < t.components; ++c) ++kinds[{!t.closed[c], t.euler_characteristic[c]}];
  std::string text = std::to_string(t.components) + (t.components == 1 ? " component:" : " components:");
  const char* separator = " ";
  for (const auto& [kind, count] : kinds) {
    text += separator + std::to_string(count) + (kind.first ? " open" : " closed") + " with Euler characteristic " +
            std::to_string(kind.second);
    separator = ", ";
  }
  if (t.boundary_edges) text += "; " + std::to_string(t.boundary_edges) + " boundary edges";
  if (t.non_manifold_edges) text += "; " + std::to_string(t.non_manifold_edges) + " non-manifold edges";
  return text;
}

void print_surface_table(const SurfaceQuality& q, const fs::path& surface, const std::vector<fs::path>& inputs) {
  std::printf("output surface      %s (%zu triangles)\ninput               ", surface.c_str(), q.triangles);
  for (std::size_t i = 0; i < inputs.size(); ++i) std::printf("%s%s", i ? ", " : "", inputs[i].c_str());
  std::printf("\nangles              min %.2f deg, max %.2f deg; %.2f%% below 30 deg, %.2f%% above 90 deg\n",
              q.min_angle_degrees, q.max_angle_degrees, q.percent_angles_below_30, q.percent_angles_above_90);
  std::printf("triangle quality    min %.3f, mean %.3f\n", q.min_quality, q.mean_quality);
  std::printf("Hausdorff distance  %.4g (%.3g%% of the input's bounding-box diagonal %.4g)\n", q.hausdorff,
              100 * q.hausdorff_relative, q.bounding_box_diagonal);
  std::printf("  input to output   %.4g\n  output to input   %.4g\n", q.input_to_output, q.output_to_input);
  if (const std::optional<double> change = q.volume_change_percent()) {
    std::printf("enclosed volume     %.6g -> %.6g (%+.2f%%)\n", *q.input_volume, *q.output_volume, *change);
    // One region is the whole: its line would repeat the one above.
    if (q.region_volumes.size() > 1) {
      for (const RegionVolume& r : q.region_volumes) {
        std::printf("  %-17s %s -> %s", r.name.c_str(), r.input ? number(*r.input).c_str() : "none",
                    r.output ? number(*r.output).c_str() : "none");
        if (const std::optional<double> region_change = r.change_percent()) std::printf(" (%+.2f%%)", *region_change);
        std::printf("\n");
      }
    }
  }
  if (q.topology_matches) {
    std::printf("topology            matches: %s\n", describe(q.output_topology).c_str());
  } else {
    std::printf("topology            DIFFERS\n  input             %s\n  output            %s\n",
                describe(q.input_topology).c_str(), describe(q.output_topology).c_str());
  }
}

void print_cell_table(const CellQuality& q, const fs::path& seeds, std::size_t seed_count) {
  std::printf("cells               %zu, of the %zu seeds in %s\n", q.cells.size(), seed_count, seeds.c_str());
  std::printf("aspect ratio        min %.4g, mean %.4g, max %.4g (cell %zu, seed %u); %zu above %.4g\n",
              q.min_aspect_ratio, q.mean_aspect_ratio, q.max_aspect_ratio, q.worst_cell, q.worst_seed,
              q.aspect_ratio_above_high, q.histogram_high);
  std::printf("cell volume         min %.4g, max %.4g, total %.10g\n", q.min_volume, q.max_volume, q.total_volume);
  std::printf("faces per cell      min %zu, mean %.2f, max %zu\n", q.min_faces, q.mean_faces, q.max_faces);
  std::printf("shortest edge       min %.4g, mean %.4g of the cube root of the cell volume (cell %zu)\n",
              q.min_shortest_edge_relative, q.mean_shortest_edge_relative, q.shortest_edge_cell);
  for (const LayerParts* layer : q.layers()) {
    if (layer->cells == 0) continue;
    const PartDistribution &edges = layer->edge_length, &faces = layer->face_area, &angles = layer->dihedral_angle;
    std::printf("%-20s%zu cells\n", layer->name, layer->cells);
    std::printf("  edges / size      min %.4g (cell %zu); %.3g%% below 0.01, %.3g%% below 0.05, %.3g%% below 0.1\n",
                edges.min, edges.min_cell, edges.percent_below(0), edges.percent_below(1), edges.percent_below(2));
    std::printf("  faces / size^2    min %.4g (cell %zu); %.3g%% below 1e-4, %.3g%% below 1e-3, %.3g%% below 0.01\n",
                faces.min, faces.min_cell, faces.percent_below(0), faces.percent_below(1), faces.percent_below(2));
    std::printf("  dihedral angles   min %.4g, mean %.4g, max %.4g degrees; %.3g%% below 10\n", angles.min, angles.mean,
                angles.max, angles.percent_below(0));
  }
  std::printf("%s\n", face_figures_line(q).c_str());
}

// The cells of OUTDIR/seeds.csv, rebuilt (compute_cells is deterministic, so they are the cells the
// run made), and their quality. Errors name the seeds file.
std::optional<CellQuality> measure_cells(const fs::path& seeds_file, std::size_t& seed_count) {
  const std::vector<Seed> seeds = read_seeds_csv(seeds_file);
  seed_count = seeds.size();
  try {
    return measure_cell_quality(compute_cells(seeds));
  } catch (const Error& e) {
    throw Error(e.kind(), "its cells cannot be measured: " + e.message(), {.file = seeds_file.string()});
  }
}

}  // namespace

int run_quality(const QualityArgs& args) {
  args.options.check();
  const fs::path out(args.output_dir);
  if (!fs::is_directory(out)) {
    throw Error(Error::Kind::UnreadableInput, "no such output folder", {.file = out.string()});
  }
  const fs::path surface = out / "surface.ply", seeds = out / "seeds.csv";
  const bool has_surface = fs::exists(surface), has_seeds = fs::exists(seeds);
  if (!has_surface && !has_seeds) {
    throw Error(Error::Kind::UnreadableInput,
                "missing, and so is seeds.csv: `vorocrust mesh INPUT -o " + out.string() +
                    "` writes the output surface and the seeds there",
                {.file = surface.string()});
  }
  std::optional<SurfaceQuality> surface_quality;
  std::vector<fs::path> inputs;
  if (has_surface) {
    inputs = input_paths(args, out);
    MeshOptions run;
    if (args.domain.given() || !fs::exists(out / "report.json")) args.domain.apply(run);
    else run = run_report_domain(out / "report.json");
    const SurfaceMesh input = read_domain(inputs, run);
    const SurfaceMesh output = read_mesh(surface);
    surface_quality = measure_surface_quality(input, output, args.options);
  }
  std::optional<CellQuality> cell_quality;
  std::size_t seed_count = 0;
  if (has_seeds) cell_quality = measure_cells(seeds, seed_count);

  const fs::path svg = out / "quality.svg";
  const std::vector<HistogramPanel> panels = quality_panels(surface_quality, cell_quality);
  const std::string title = !cell_quality      ? "surface quality: " + surface.string()
                            : !surface_quality ? "cell quality: " + seeds.string()
                                               : "surface and cell quality: " + out.string();
  write_histogram_svg(svg, title, panels);

  if (args.json) {
    std::printf("%s\n", quality_json(surface_quality ? &*surface_quality : nullptr,
                                     cell_quality ? &*cell_quality : nullptr)
                             .c_str());
    return kOk;
  }
  if (surface_quality) print_surface_table(*surface_quality, surface, inputs);
  if (cell_quality) print_cell_table(*cell_quality, seeds, seed_count);
  std::printf("histogram%s          %s\n", panels.size() > 1 ? "s" : " ", svg.c_str());
  return kOk;
}

}  // namespace vorocrust::cli
