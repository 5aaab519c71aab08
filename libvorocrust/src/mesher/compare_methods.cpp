// VoroCrust against clipping: two runs of one job at one sizing, measured alike.
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/c_format.hpp"
#include "vorocrust/atomic_file.hpp"
#include "vorocrust/compare.hpp"
#include "vorocrust/quality_svg.hpp"
#include "vorocrust/regions.hpp"

namespace vorocrust {
namespace {

double meshing_seconds(const MeshResult& mesh) {
  double seconds = 0;
  for (const PhaseTiming& t : mesh.timings) seconds += t.seconds;
  return seconds;
}

MethodRun run_with(const Job& job, Method method, double max_size, const ProgressCallback& progress,
                   const WarningCallback& warn, Comparison& comparison) {
  Job run = job;
  run.options.method = method;
  run.options.max_size = max_size;
  if (!job.output_dir.empty()) run.output_dir = job.output_dir / to_string(method);
  const JobResult result = run_job(run, progress, warn);
  comparison.enclosed_volume = materials_volume(result.mesh.regions);
  return {method, max_size, meshing_seconds(result.mesh),
          measure_method_figures(result.mesh.cells, comparison.enclosed_volume)};
}

HistogramPanel edge_ratio_panel(const MethodRun& run) {
  HistogramPanel panel;
  panel.label = c_format("%s: boundary faces' shortest over longest edge (%zu faces)", to_string(run.method),
                         run.figures.boundary_faces);
  panel.low = 0;
  panel.high = 1;
  panel.counts = run.figures.boundary_edge_ratio_histogram;
  panel.min = run.figures.boundary_edge_ratio_min;
  panel.mean = run.figures.boundary_edge_ratio_mean;
  return panel;
}

std::string comparison_json(const Comparison& comparison) {
  nlohmann::ordered_json out;
  out["enclosed_volume"] = comparison.enclosed_volume;
  for (const MethodRun& run : comparison.runs) {
    const MethodFigures& f = run.figures;
    nlohmann::ordered_json m;
    m["method"] = to_string(run.method);
    m["max_size"] = std::isfinite(run.max_size) ? nlohmann::ordered_json(run.max_size) : nlohmann::ordered_json();
    m["seconds"] = run.seconds;
    m["cells"] = f.cells;
    m["faces"] = f.faces;
    m["boundary_faces"] = f.boundary_faces;
    m["boundary_edge_ratio"] = {{"min", f.boundary_edge_ratio_min},
                                {"mean", f.boundary_edge_ratio_mean},
                                {"below_0.1", f.boundary_edge_ratio_below_tenth},
                                {"histogram", f.boundary_edge_ratio_histogram}};
    m["boundary_angle_min_degrees"] = f.boundary_angle_min;
    m["faces_per_cell"] = f.faces_per_cell;
    m["non_convex_cells"] = f.non_convex_cells;
    m["off_link_faces"] = f.off_link_faces;
    m["link_angle_max_degrees"] = f.link_angle_max;
    m["volume"] = f.volume;
    m["volume_error"] = f.volume_error;
    out["methods"].push_back(std::move(m));
  }
  return out.dump(2) + "\n";
}

}  // namespace

Comparison compare_methods(const Job& job, const ProgressCallback& progress, const WarningCallback& warn) {
  Comparison comparison;
  const double max_size = job.options.max_size;
  comparison.runs.push_back(run_with(job, Method::Vorocrust, max_size, progress, warn, comparison));
  const MethodFigures& vorocrust = comparison.runs.front().figures;
  const double radius =
      std::isfinite(max_size) ? max_size : std::cbrt(vorocrust.volume / static_cast<double>(vorocrust.cells));
  comparison.runs.push_back(run_with(job, Method::Clipped, radius, progress, warn, comparison));
  if (!job.output_dir.empty()) {
    write_file_atomically(job.output_dir / "compare.json", comparison_json(comparison));
    std::vector<HistogramPanel> panels;
    for (const MethodRun& run : comparison.runs) panels.push_back(edge_ratio_panel(run));
    write_file_atomically(job.output_dir / "compare.svg",
                          histogram_svg("VoroCrust against clipping: the shape of the boundary faces", panels));
  }
  return comparison;
}

std::string comparison_table(const Comparison& comparison) {
  std::string table = c_format("%-44s", "");
  for (const MethodRun& run : comparison.runs) table += c_format("%14s", to_string(run.method));
  table += "\n";
  const auto row = [&](const char* name, auto value) {
    table += c_format("%-44s", name);
    for (const MethodRun& run : comparison.runs) table += value(run);
    table += "\n";
  };
  const auto number = [](double x) { return c_format("%14.4g", x); };
  const auto count = [](std::size_t n) { return c_format("%14zu", n); };
  row("max size (seed radius for clipped)", [&](const MethodRun& r) { return number(r.max_size); });
  row("cells", [&](const MethodRun& r) { return count(r.figures.cells); });
  row("boundary faces", [&](const MethodRun& r) { return count(r.figures.boundary_faces); });
  row("boundary face shortest/longest edge, min",
      [&](const MethodRun& r) { return number(r.figures.boundary_edge_ratio_min); });
  row("boundary face shortest/longest edge, mean",
      [&](const MethodRun& r) { return number(r.figures.boundary_edge_ratio_mean); });
  row("boundary faces with that ratio below 0.1",
      [&](const MethodRun& r) { return count(r.figures.boundary_edge_ratio_below_tenth); });
  row("smallest boundary face angle (degrees)",
      [&](const MethodRun& r) { return number(r.figures.boundary_angle_min); });
  row("faces per cell", [&](const MethodRun& r) { return number(r.figures.faces_per_cell); });
  row("non-convex cells", [&](const MethodRun& r) { return count(r.figures.non_convex_cells); });
  row("faces off their seed link (> 0.05 degrees)",
      [&](const MethodRun& r) { return count(r.figures.off_link_faces); });
  row("volume error against the input", [&](const MethodRun& r) { return number(r.figures.volume_error); });
  row("seconds", [&](const MethodRun& r) { return number(r.seconds); });
  return table;
}

}  // namespace vorocrust
