// vorocrust/report.hpp — the JSON documents the front ends print and write (`info --json`,
// OUTDIR/report.json), produced in one place so every front end says the same thing.
#pragma once

#include <string>
#include <vector>

#include "vorocrust/mesh_info.hpp"
#include "vorocrust/mesher.hpp"
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

}  // namespace vorocrust
