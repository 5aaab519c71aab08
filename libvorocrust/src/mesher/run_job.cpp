// A whole mesh run as every front end runs it: read, validate, mesh, write, summarise.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <regex>

#include "core/memory.hpp"
#include "features/scan_likeness.hpp"
#include "vorocrust/atomic_file.hpp"
#include "vorocrust/balls.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/job.hpp"
#include "vorocrust/mesher.hpp"
#include "vorocrust/quality_svg.hpp"
#include "vorocrust/read_mesh.hpp"
#include "vorocrust/report.hpp"
#include "vorocrust/seeds.hpp"
#include "vorocrust/threads.hpp"
#include "vorocrust/write_mesh.hpp"
#include "vorocrust/write_volume_mesh.hpp"
#include "vorocrust/write_vtu.hpp"

namespace vorocrust {

namespace {

namespace fs = std::filesystem;

// The time of every phase, split where the reported phase changes: the job's own (reading,
// validating, writing) and the pipeline's, as its progress callback names them.
class PhaseRecorder {
 public:
  explicit PhaseRecorder(const ProgressCallback& forward) : forward_(forward) {}

  bool update(const ProgressUpdate& update) {
    if (update.phase != phase_) begin(std::string(update.phase));
    return !forward_ || forward_(update);
  }
  // A phase of the job's own; throws Error(Cancelled) when the caller asks to stop.
  void begin_own(const std::string& phase) {
    if (!update({phase, -1})) throw Error(Error::Kind::Cancelled, "cancelled");
  }
  std::vector<PhaseTiming> finish() {
    begin("");
    return timings_;
  }
  ProgressCallback callback() {
    return [this](const ProgressUpdate& u) { return update(u); };
  }

 private:
  void begin(std::string phase) {
    const auto now = std::chrono::steady_clock::now();
    if (!phase_.empty()) {
      timings_.push_back({phase_, std::chrono::duration<double>(now - start_).count(), peak_resident_bytes()});
    }
    phase_ = std::move(phase);
    start_ = now;
  }

  const ProgressCallback& forward_;
  std::string phase_;
  std::chrono::steady_clock::time_point start_;
  std::vector<PhaseTiming> timings_;
};

// Refuses, before any work, an output folder that cannot be made or written into.
void check_output_folder(const fs::path& folder) {
  std::error_code ec;
  fs::path existing = fs::absolute(folder, ec);
  while (!existing.empty() && !fs::exists(existing, ec) && existing.has_parent_path() && existing != existing.parent_path()) {
    existing = existing.parent_path();
  }
  if (!fs::is_directory(existing, ec) || ::access(existing.c_str(), W_OK) != 0) {
    throw Error(Error::Kind::Output,
                std::string("cannot create the output folder: ") +
                    (fs::exists(folder, ec) ? "not a folder" : existing.string() + " is not a folder it can write into"),
                {.file = folder.string()});
  }
}

void make_folder(const fs::path& folder) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec || !fs::is_directory(folder)) {
    throw Error(Error::Kind::Output, "cannot create the output folder: " + (ec ? ec.message() : "not a folder"),
                {.file = folder.string()});
  }
}

// A folder inside the output folder where the outputs are written before they move into place;
// removed with whatever it still holds when the job ends.
class Staging {
 public:
  explicit Staging(const fs::path& out)
      : out_(out), path_(out / (".vorocrust-staging-" + std::to_string(::getpid()))) {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
    make_folder(path_);
  }
  ~Staging() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  Staging(const Staging&) = delete;
  Staging& operator=(const Staging&) = delete;

  const fs::path& path() const { return path_; }

  // Moves every staged entry over its namesake in the output folder, and removes `stale`
  // entries there that were not staged.
  std::vector<fs::path> commit(const std::vector<std::string_view>& stale) {
    std::vector<fs::path> staged, moved;
    for (const fs::directory_entry& entry : fs::directory_iterator(path_)) staged.push_back(entry.path().filename());
    for (std::string_view name : stale) {
      std::error_code ignored;
      if (std::find(staged.begin(), staged.end(), fs::path(name)) == staged.end()) fs::remove_all(out_ / name, ignored);
    }
    for (const fs::directory_entry& entry : fs::directory_iterator(path_)) {
      const fs::path target = out_ / entry.path().filename();
      std::error_code ec;
      fs::remove_all(target, ec);
      if (!ec) fs::rename(entry.path(), target, ec);
      if (ec) throw Error(Error::Kind::Output, "cannot write: " + ec.message(), {.file = target.string()});
      moved.push_back(target);
    }
    std::sort(moved.begin(), moved.end());
    return moved;
  }

 private:
  fs::path out_, path_;
};

// Writes the formats of `options.formats` that `result` reached into `staged`; the files name
// `out`, where they will be (quality.svg's title).
void write_outputs(const MeshResult& result, const MeshOptions& options, const ReportPage& page, const fs::path& staged,
                   const fs::path& out) {
  const auto wanted = [&](OutputFormat f) {
    return options.writes(f) && options.stop_after >= output_format(f).needs;
  };
  // A clipped mesh has no balls: no empty balls.csv beside it.
  if (wanted(OutputFormat::Balls) && options.method != Method::Clipped) {
    write_balls_csv(result.balls, staged / "balls.csv");
    write_balls_vtk(result.balls, staged / "balls.vtk");
    // The surface the balls cover, when smoothing changed it: `check-balls` verifies against it.
    if (result.features.smoothing_iterations > 0) write_mesh(result.smoothed_input, staged / "smoothed_surface.ply");
  }
  if (wanted(OutputFormat::Seeds)) write_seeds_csv(result.seeds, staged / "seeds.csv");
  if (wanted(OutputFormat::SurfaceObj)) write_mesh(result.surface, staged / "surface.obj");
  if (wanted(OutputFormat::SurfacePly)) write_mesh(result.surface, staged / "surface.ply");
  const CellQuality* quality = result.cell_quality ? &*result.cell_quality : nullptr;
  for (const OutputFormatSpec& f : output_formats()) {
    if (f.volume && wanted(f.format)) write_volume_format(result.cells, staged, f.name, quality);
  }
  // The dual tetrahedra belong to a clipped mesh, whose seeds on the surface make them fill it.
  if (wanted(OutputFormat::Tets) && options.method == Method::Clipped) write_tets_vtu(result.cells, staged / "tets.vtu");
  if (wanted(OutputFormat::QualitySvg)) {
    write_histogram_svg(staged / "quality.svg", "quality: " + (out / "surface.ply").string(),
                        quality_panels(result.surface_quality, result.cell_quality));
  }
  if (wanted(OutputFormat::ReportHtml)) write_report_html(staged / "report.html", result, page);
}

// Every file name an output format may leave in a folder.
std::vector<std::string_view> output_file_names() {
  std::vector<std::string_view> names;
  for (const OutputFormatSpec& f : output_formats()) names.insert(names.end(), f.files.begin(), f.files.end());
  return names;
}

void validate_input(JobResult& result, const MeshOptions& options, const WarningCallback& warn) {
  result.validation =
      validate(result.input, {.self_intersections_are_errors = options.self_intersections == SelfIntersections::Refuse});
  for (const Finding& f : result.validation.findings) {
    if (f.severity == Finding::Severity::Error) {
      if (f.code == "self-intersection") {
        throw Error(Error::Kind::InvalidGeometry,
                    f.message + " (self_intersections resolve cuts them along their intersection curves)",
                    {.option = "self_intersections"});
      }
      throw Error(Error::Kind::InvalidGeometry, f.message);
    }
    if (f.severity == Finding::Severity::Note) continue;
    result.warnings.push_back(std::string(to_string(f.severity)) + ": " + f.message);
    if (warn) warn(result.warnings.back());
  }
}

// The paper's sharp-edge rule turns a scan's folds into a crowd of tiny creases and corners; said
// before the refinement, with the options that mesh it well (features/scan_likeness.hpp).
void suggest_smooth(JobResult& result, const MeshOptions& options, const WarningCallback& warn) {
  if (options.smooth) return;
  const features::SharpBends bends = features::sharp_bends(result.input, options.sharp_angle() * std::numbers::pi / 180);
  if (!bends.looks_like_scan()) return;
  const auto percent = static_cast<int>(std::lround(100.0 * static_cast<double>(bends.near_sharp_angle) /
                                                    static_cast<double>(bends.sharp_edges)));
  result.warnings.push_back(
      "warning: the surface looks like a scan or a tessellation of a curved shape: " +
      std::to_string(bends.sharp_edges) + " of its edges bend past `sharp_angle` (" +
      std::to_string(static_cast<int>(std::lround(options.sharp_angle()))) + " degrees), " + std::to_string(percent) +
      " % of them by less than 15 degrees more, in " + std::to_string(bends.chains) + " chains of " +
      std::to_string(bends.median_chain) + (bends.median_chain == 1 ? " edge" : " edges") +
      " at the median: each would be protected as a crease. Mesh it with `smooth`, or with a larger "
      "`sharp_angle` to keep only its true creases");
  if (warn) warn(result.warnings.back());
}

// tets.vtu belongs to a clipped mesh, whose seeds on the surface make the tetrahedra fill it.
// Asked for by name on a VoroCrust run (the default, every format, asks for all), it is said
// that none will come, rather than the file silently missing.
void warn_unwritten_tets(JobResult& result, const MeshOptions& options, const WarningCallback& warn) {
  if (options.method == Method::Clipped || !options.writes(OutputFormat::Tets) ||
      options.formats == MeshOptions::all_output_formats()) {
    return;
  }
  result.warnings.push_back(
      "warning: `formats` asks for tets (tets.vtu), the tetrahedra dual to a clipped mesh; a VoroCrust mesh has "
      "none, so none is written (`method` 'clipped' makes a clipped mesh)");
  if (warn) warn(result.warnings.back());
}

RunReport report_of(const Job& job) {
  RunReport report;
  report.command = job.command;
  for (const fs::path& p : job.inputs) report.inputs.push_back(p.string());
  report.options = job.options;
  return report;
}

void write_report(const Job& job, RunReport report) {
  write_file_atomically(job.output_dir / "report.json", run_report_json(report) + "\n");
}

}  // namespace

JobResult run_job(const Job& job, const ProgressCallback& progress, const WarningCallback& warn) {
  const MeshOptions& options = job.options;
  options.check();
  const ThreadLimit threads(options.threads);
  if (!job.output_dir.empty()) check_output_folder(job.output_dir);
  JobResult result;
  PhaseRecorder phases(progress);
  RunReport report = report_of(job);
  try {
    phases.begin_own("reading");
    if (job.model) {
      result.input = *job.model;
    } else {
      result.input = read_meshes(job.inputs);
    }
    report.mesh = &result.input;
    phases.begin_own("validating");
    validate_input(result, options, warn);
    suggest_smooth(result, options, warn);
    warn_unwritten_tets(result, options, warn);
    result.info = mesh_info(result.input);
    report.input = &result.info;
    report.validation = &result.validation;

    result.mesh = generate_mesh(result.input, options, phases.callback());
    report.result = &result.mesh;
    for (std::string& line : run_warnings(result.mesh)) {
      if (warn) warn(line);
      result.warnings.push_back(std::move(line));
    }
    result.summary = run_summary(result.mesh, options);

    if (!job.output_dir.empty()) {
      phases.begin_own("writing");
      make_folder(job.output_dir);
      Staging staging(job.output_dir);
      write_outputs(result.mesh, options, job_report_page(job, result), staging.path(), job.output_dir);
      result.written = staging.commit(output_file_names());
      std::vector<OutputFormat> reached;
      for (OutputFormat f : options.formats) {
        if (options.stop_after >= output_format(f).needs) reached.push_back(f);
      }
      for (std::string& line : written_lines(job.output_dir, reached)) result.summary.push_back(std::move(line));
    }
    result.timings = phases.finish();
    if (!job.output_dir.empty()) {
      report.timings = result.timings;
      report.status = "ok";
      write_report(job, report);
      result.written.push_back(job.output_dir / "report.json");
    }
    return result;
  } catch (const Error& e) {
    // A failed run says why in an output folder that exists; it makes none.
    std::error_code ec;
    if (!job.output_dir.empty() && fs::is_directory(job.output_dir, ec)) {
      report.timings = phases.finish();
      report.status = to_string(e.kind());
      report.message = e.what();
      write_report(job, report);
    }
    throw;
  }
}

ReportPage job_report_page(const Job& job, const JobResult& result) {
  ReportPage page;
  for (const fs::path& input : job.inputs) page.title += (page.title.empty() ? "" : ", ") + input.filename().string();
  if (page.title.empty()) page.title = "a model";
  page.summary = result.summary;
  page.warnings = result.warnings;
  page.timings = result.timings.empty() ? result.mesh.timings : result.timings;
  return page;
}

std::string job_report_json(const Job& job, const JobResult& result, int indent) {
  RunReport report = report_of(job);
  report.mesh = &result.input;
  report.input = &result.info;
  report.validation = &result.validation;
  report.result = &result.mesh;
  report.timings = result.timings;
  report.status = "ok";
  return run_report_json(report, indent);
}

}  // namespace vorocrust
