// A whole 2D run: the domain, the mesh, its files and report.json.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>

#include "vorocrust/atomic_file.hpp"
#include "vorocrust/plane.hpp"
#include "vorocrust/version.hpp"
#include "vorocrust/write_volume_mesh.hpp"

namespace vorocrust {

namespace {

using nlohmann::json;

constexpr const char* kFormats[] = {"vtu", "svg", "openfoam", "tough", "pflotran", "exodus", "seeds"};

// Where each format goes in the output folder.
const char* file_of(const std::string& format) {
  if (format == "vtu") return "mesh.vtu";
  if (format == "svg") return "mesh.svg";
  if (format == "openfoam") return "case";
  if (format == "tough") return "MESH";
  if (format == "pflotran") return "pflotran";
  if (format == "exodus") return "mesh.exo";
  return "seeds.csv";
}

json report_of(const PlaneJob& job, const PlaneMesh* mesh, const PlaneQuality* quality, const PlanarDomain* domain) {
  json r;
  r["program"] = "vorocrust " VOROCRUST_VERSION;
  r["dimension"] = 2;
  r["command"] = job.command;
  r["input"] = job.input.string();
  const PlaneOptions& o = job.options;
  r["options"] = {{"lipschitz", o.lipschitz},
                  {"max_size", std::isfinite(o.max_size) ? json(o.max_size) : json(nullptr)},
                  {"sizing", o.sizing_file.string()},
                  {"sharp_angle", o.sharp_angle_degrees},
                  {"interior", to_string(o.interior)},
                  {"cvt_iterations", o.cvt_iterations},
                  {"seed", o.seed},
                  {"threads", o.threads},
                  {"thickness", job.thickness}};
  if (domain) {
    r["domain"] = {{"points", domain->points.size()}, {"segments", domain->segments.size()},
                   {"holes", domain->holes.size()}, {"region_points", domain->regions.size()}};
  }
  if (!mesh) return r;
  const PlaneStats& s = mesh->stats;
  r["features"] = {{"corners", s.corners}, {"chains", s.chains}};
  r["refinement"] = {{"circles", s.circles}, {"rounds", s.refinement_rounds}};
  r["seeds"] = {{"pairs", s.pair_seeds / 2}, {"pair_seeds", s.pair_seeds}, {"cap_seeds", s.cap_seeds},
                {"interior_seeds", s.interior_seeds}, {"outside_seeds", s.outside_seeds}};
  json seconds = json::object();
  double total = 0;
  for (const auto& [phase, t] : s.seconds) {
    seconds[phase] = seconds.value(phase, 0.0) + t;
    total += t;
  }
  seconds["total"] = total;
  r["seconds"] = seconds;
  json areas = json::object();
  for (std::size_t l = 1; l < quality->area_by_region.size(); ++l) {
    if (quality->area_by_region[l] != 0) areas[l < mesh->region_names.size() ? mesh->region_names[l] : std::to_string(l)] = quality->area_by_region[l];
  }
  r["cells"] = {{"cells", quality->cells},
                {"points", mesh->points.size()},
                {"edges", quality->edges},
                {"boundary_edges", quality->boundary_edges},
                {"interface_edges", quality->interface_edges},
                {"area_by_region", areas},
                {"convex", quality->convex},
                {"quality",
                 {{"angle", {{"min", quality->min_angle}, {"max", quality->max_angle}}},
                  {"aspect_ratio", {{"max", quality->max_aspect_ratio}, {"mean", quality->mean_aspect_ratio},
                                    {"definition", "radius of the smallest enclosing circle / radius of the largest inscribed circle"}}},
                  {"shortest_edge", {{"min", quality->min_shortest_edge}, {"below_0_01", quality->edges_below_0_01},
                                     {"below_0_1", quality->edges_below_0_1},
                                     {"definition", "edge length / square root of its cell's area"}}},
                  {"link_angle", {{"max", quality->max_link_angle},
                                  {"definition", "degrees by which an edge between two cells departs from orthogonal to their seeds' link"}}}}}};
  return r;
}

void write_report(const PlaneJob& job, json report) {
  if (job.output_dir.empty()) return;
  write_file_atomically(job.output_dir / "report.json", report.dump(2) + "\n");
}

}  // namespace

std::vector<std::string> plane_format_names() { return {std::begin(kFormats), std::end(kFormats)}; }

PlaneJobResult run_plane_job(const PlaneJob& job) {
  std::vector<std::string> formats = job.formats.empty() ? plane_format_names() : job.formats;
  for (const std::string& f : formats) {
    if (std::find(std::begin(kFormats), std::end(kFormats), f) == std::end(kFormats)) {
      std::string known;
      for (const char* k : kFormats) known += (known.empty() ? "" : ", ") + std::string(k);
      throw Error(Error::Kind::Usage, "unknown 2D format '" + f + "': expected " + known, {.option = "format"});
    }
  }
  if (!(job.thickness > 0) || !std::isfinite(job.thickness)) {
    throw Error(Error::Kind::Usage, "thickness must be positive", {.option = "thickness"});
  }
  job.options.check();
  if (!job.output_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(job.output_dir, ec);
    if (ec || !std::filesystem::is_directory(job.output_dir)) {
      throw Error(Error::Kind::Output, "cannot create the output folder", {.file = job.output_dir.string()});
    }
  }
  PlaneJobResult result;
  PlanarDomain domain;
  try {
    domain = job.domain ? *job.domain : read_planar_domain(job.input);
    result.mesh = mesh_plane(domain, job.options);
    const auto timed = [&](const char* phase, auto&& work) {
      const auto begin = std::chrono::steady_clock::now();
      work();
      result.mesh.stats.seconds.emplace_back(phase, std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count());
    };
    timed("quality", [&] { result.quality = measure_plane_quality(result.mesh); });
    const auto begin_writing = std::chrono::steady_clock::now();
    if (!job.output_dir.empty()) {
      std::optional<VoronoiMesh> slab;
      for (const char* f : kFormats) {
        const std::string format = f;
        const std::filesystem::path where = job.output_dir / file_of(format);
        if (std::find(formats.begin(), formats.end(), format) == formats.end()) {
          std::error_code ignored;
          std::filesystem::remove_all(where, ignored);  // no file of an earlier run passes for this one's
          continue;
        }
        if (format == "vtu") write_plane_vtu(result.mesh, where, &result.quality);
        else if (format == "svg") write_plane_svg(result.mesh, where);
        else if (format == "seeds") write_seeds_csv(result.mesh.seeds, where);
        else {
          if (!slab) slab = extrude_plane_mesh(result.mesh, job.thickness);
          write_volume_format(*slab, job.output_dir, format);
        }
      }
    }
    result.mesh.stats.seconds.emplace_back("writing", std::chrono::duration<double>(std::chrono::steady_clock::now() - begin_writing).count());
    json report = report_of(job, &result.mesh, &result.quality, &result.mesh.domain);
    report["status"] = "ok";
    write_report(job, report);
  } catch (const Error& e) {
    json report = report_of(job, nullptr, nullptr, nullptr);
    report["status"] = "failed";
    report["error"] = {{"kind", to_string(e.kind())}, {"message", e.what()}};
    try {
      write_report(job, report);
    } catch (const Error&) {
    }
    throw;
  }
  const PlaneQuality& q = result.quality;
  char line[256];
  std::snprintf(line, sizeof line, "%zu cells, %zu circles, %zu seed pairs; areas by region:", q.cells,
                result.mesh.stats.circles, result.mesh.stats.pair_seeds / 2);
  std::string text = line;
  for (std::size_t l = 1; l < q.area_by_region.size(); ++l) {
    if (q.area_by_region[l] == 0) continue;
    std::snprintf(line, sizeof line, " %s %.6g", result.mesh.region_names[l].c_str(), q.area_by_region[l]);
    text += line;
  }
  result.summary.push_back(text);
  std::snprintf(line, sizeof line, "angles %.1f to %.1f degrees, aspect ratio at most %.2f, shortest edge %.3g of its cell's size",
                q.min_angle, q.max_angle, q.max_aspect_ratio, q.min_shortest_edge);
  result.summary.push_back(line);
  return result;
}

}  // namespace vorocrust
