// vorocrust/report.hpp — the JSON documents the front ends print and write (`info --json`,
// OUTDIR/report.json, `quality --json`), produced in one place so every front end says the same
// thing.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "vorocrust/mesh_info.hpp"
#include "vorocrust/mesher.hpp"
#include "vorocrust/quality.hpp"
#include "vorocrust/validate.hpp"

namespace vorocrust {

// One JSON object: counts, components, groups, regions, bounding box, shell volumes, findings.
std::string info_json(const std::vector<std::string>& inputs, const SurfaceMesh& mesh, const MeshInfo& info,
                      const ValidationReport& validation, int indent = 2);

// What OUTDIR/report.json holds for one `mesh` run, whatever its outcome.
struct RunReport {
  std::vector<std::string> command;  // argv as given
  std::vector<std::string> inputs;
  MeshOptions options;
  const SurfaceMesh* mesh = nullptr;  // null when reading failed
  const MeshInfo* input = nullptr;
  const ValidationReport* validation = nullptr;
  const MeshResult* result = nullptr;  // null until the pipeline returned
  std::vector<PhaseTiming> timings;
  std::string status;   // "ok", or the failure class ("not yet implemented", "invalid geometry", ...)
  std::string message;  // one line; empty on success
};

std::string run_report_json(const RunReport& report, int indent = 2);

// The `inputs` list of an OUTDIR/report.json, as the run was given them (relative paths are
// relative to the folder that run started in). Throws Error(UnreadableInput) naming the file
// when it is missing, is not JSON or has no list of input paths.
std::vector<std::string> run_report_inputs(const std::filesystem::path& report_json);

// The surface-quality figures (quality.hpp) as one JSON object, every key saying its unit:
// angles in degrees, shares in percent, distances in the input's units and in percent of its
// bounding-box diagonal.
std::string surface_quality_json(const SurfaceQuality& quality, int indent = 2);

}  // namespace vorocrust
