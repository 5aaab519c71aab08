// vorocrust/job.hpp — a whole mesh run as every front end runs it: read or take the model,
// validate it, mesh it, write the chosen outputs, and say what was done.
//
// The CLI's `mesh`, the Python module's mesh(), the MeshLab filter and the FreeCAD workbench all
// call run_job; they only translate their arguments into a Job and show its JobResult.
//
// Contract of run_job(job, progress, warn):
// - The model: job.model when set (a surface from arrays, MeshLab layers, FreeCAD objects), else
//   job.inputs read and merged (read_meshes). job.inputs name the model in report.json either way.
// - job.options.check() first: Error(Usage) naming the option. Then validation: a finding of
//   severity Error stops the run with Error(InvalidGeometry) and the finding's message; warnings
//   go to `warn` as they are found (and into JobResult::warnings).
// - generate_mesh up to options.stop_after, reporting to `progress`; returning false cancels
//   (Error(Cancelled)).
// - With an output folder: one that cannot be made or written into is refused first
//   (Error(Output)); it is made only once the run has something to write. Every format in
//   options.formats that the run reached is written; files of the formats the run did not write
//   (not asked for, or not reached) are removed, so that no file of an earlier run in the same
//   folder passes for this run's. The outputs are written into a staging folder inside it and
//   moved into place once all are complete: a run that fails or is cancelled leaves the files
//   of the run before it as they were. report.json is written last; a run that fails writes it
//   too, with its status and message, into an output folder that exists (and makes none), and
//   the Error is rethrown.
// - The timings cover every phase, reading and writing included, one entry per phase change
//   reported to progress (a refinement pass is one), as report.json lists them.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "vorocrust/api.hpp"
#include "vorocrust/mesh_info.hpp"
#include "vorocrust/mesh_result.hpp"
#include "vorocrust/options.hpp"
#include "vorocrust/progress.hpp"
#include "vorocrust/report_html.hpp"
#include "vorocrust/stats.hpp"
#include "vorocrust/surface_mesh.hpp"
#include "vorocrust/validate.hpp"

namespace vorocrust {

struct VOROCRUST_API Job {
  std::vector<std::filesystem::path> inputs;  // files to read and merge (or what names job.model)
  std::optional<SurfaceMesh> model;           // a model in memory, used instead of reading inputs
  MeshOptions options;
  std::filesystem::path output_dir;           // empty: nothing is written
  std::vector<std::string> command;           // the command line, for report.json
};

struct VOROCRUST_API JobResult {
  SurfaceMesh input;             // the model as meshed: read, its orientation made consistent
  MeshInfo info;                 // its description (mesh_info)
  ValidationReport validation;   // what validation found
  MeshResult mesh;               // every stage's result and figures
  std::vector<PhaseTiming> timings;
  std::vector<std::string> warnings;   // validation's warnings and notes on what the run changed
  std::vector<std::string> summary;    // the run's figures, a line each, as the front ends print them
  std::vector<std::filesystem::path> written;  // every file and folder written, report.json last
};

using WarningCallback = std::function<void(const std::string&)>;

VOROCRUST_API JobResult run_job(const Job& job, const ProgressCallback& progress = {}, const WarningCallback& warn = {});

// report.json of a finished job, as run_job writes it (the Python module's report()).
VOROCRUST_API std::string job_report_json(const Job& job, const JobResult& result, int indent = 2);

// What report.html of a job shows besides its result: the inputs' names as title, the summary
// lines, the warnings and the timings (the job's, or the pipeline's while the job runs).
VOROCRUST_API ReportPage job_report_page(const Job& job, const JobResult& result);

}  // namespace vorocrust
