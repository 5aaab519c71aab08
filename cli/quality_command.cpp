#include "quality_command.hpp"

#include <cstdio>
#include <filesystem>
#include <map>
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

void print_table(const SurfaceQuality& q, const fs::path& surface, const std::vector<fs::path>& inputs,
                 const fs::path& svg) {
  std::printf("output surface      %s (%zu triangles)\ninput               ", surface.c_str(), q.triangles);
  for (std::size_t i = 0; i < inputs.size(); ++i) std::printf("%s%s", i ? ", " : "", inputs[i].c_str());
  std::printf("\nangles              min %.2f deg, max %.2f deg; %.2f%% below 30 deg, %.2f%% above 90 deg\n",
              q.min_angle_degrees, q.max_angle_degrees, q.percent_angles_below_30, q.percent_angles_above_90);
  std::printf("triangle quality    min %.3f, mean %.3f\n", q.min_quality, q.mean_quality);
  std::printf("Hausdorff distance  %.4g (%.3g%% of the input's bounding-box diagonal %.4g)\n", q.hausdorff,
              100 * q.hausdorff_relative, q.bounding_box_diagonal);
  std::printf("  input to output   %.4g\n  output to input   %.4g\n", q.input_to_output, q.output_to_input);
  if (q.topology_matches) {
    std::printf("topology            matches: %s\n", describe(q.output_topology).c_str());
  } else {
    std::printf("topology            DIFFERS\n  input             %s\n  output            %s\n",
                describe(q.input_topology).c_str(), describe(q.output_topology).c_str());
  }
  std::printf("histogram           %s\n", svg.c_str());
}

}  // namespace

int run_quality(const QualityArgs& args) {
  args.options.check();
  const fs::path out(args.output_dir);
  if (!fs::is_directory(out)) {
    throw Error(Error::Kind::UnreadableInput, "no such output folder", {.file = out.string()});
  }
  const fs::path surface = out / "surface.ply";
  if (!fs::exists(surface)) {
    throw Error(Error::Kind::UnreadableInput,
                "missing: `vorocrust mesh INPUT -o " + out.string() + "` writes the output surface there",
                {.file = surface.string()});
  }
  const std::vector<fs::path> inputs = input_paths(args, out);
  const SurfaceMesh input = read_meshes(inputs);
  const SurfaceMesh output = read_mesh(surface);
  const SurfaceQuality q = measure_surface_quality(input, output, args.options);

  const fs::path svg = out / "quality.svg";
  write_histogram_svg(svg, "surface quality: " + surface.string(), {surface_quality_panel(q)});

  if (args.json) {
    std::printf("%s\n", surface_quality_json(q).c_str());
  } else {
    print_table(q, surface, inputs, svg);
  }
  return kOk;
}

}  // namespace vorocrust::cli
