// vorocrust/report.hpp — the JSON documents the front ends print and write (`info --json`,
// OUTDIR/report.json, `quality --json`), produced in one place so every front end says the same
// thing.
#pragma once

#include "vorocrust/api.hpp"

#include <filesystem>
#include <string>
#include <vector>

#include "vorocrust/cell_quality.hpp"
#include "vorocrust/cells.hpp"
#include "vorocrust/mesh_info.hpp"
#include "vorocrust/mesh_result.hpp"
#include "vorocrust/options.hpp"
#include "vorocrust/stats.hpp"
#include "vorocrust/quality.hpp"
#include "vorocrust/validate.hpp"

namespace vorocrust {

// One JSON object: counts, components, groups, regions, bounding box, shell volumes, findings;
// for an input validation accepts, "region_details" (find_regions: per label its name, pieces,
// sides and volume) or "region_error" (why the regions contradict the input's labels).
VOROCRUST_API std::string info_json(const std::vector<std::string>& inputs, const SurfaceMesh& mesh, const MeshInfo& info,
                      const ValidationReport& validation, int indent = 2);

// What OUTDIR/report.json holds for one `mesh` run, whatever its outcome.
struct VOROCRUST_API RunReport {
  std::vector<std::string> command;  // argv as given
  std::vector<std::string> inputs;
  MeshOptions options;
  const SurfaceMesh* mesh = nullptr;  // null when reading failed
  const MeshInfo* input = nullptr;
  const ValidationReport* validation = nullptr;
  const MeshResult* result = nullptr;  // null until the pipeline returned
  // Every phase as it ran; "timings" in the report holds one {phase, seconds, runs} per phase, a
  // refinement pass ("refinement: patches, pass 3") counted as a run of its phase.
  std::vector<PhaseTiming> timings;
  std::string status;   // "ok", or the failure class ("not yet implemented", "invalid geometry", ...)
  std::string message;  // one line; empty on success
};

VOROCRUST_API std::string run_report_json(const RunReport& report, int indent = 2);

// The `inputs` list of an OUTDIR/report.json, as the run was given them (relative paths are
// relative to the folder that run started in). Throws Error(UnreadableInput) naming the file
// when it is missing, is not JSON or has no list of input paths.
VOROCRUST_API std::vector<std::string> run_report_inputs(const std::filesystem::path& report_json);

// The surface a mesh run started from, as its OUTDIR/report.json records it: `options.box` and
// `options.self_intersections` set from its "options" (those it does not hold keep their
// defaults). Throws Error(UnreadableInput) naming the file when it is missing or is not JSON, or
// holds a box or mode of the wrong form.
VOROCRUST_API MeshOptions run_report_domain(const std::filesystem::path& report_json);

// The region names of a mesh run's OUTDIR/report.json ("surface": {"regions"}), by label; empty
// when the file is missing, unreadable or names none (the seeds then go unnamed).
VOROCRUST_API std::vector<std::string> run_report_regions(const std::filesystem::path& report_json);

// The surface-quality figures (quality.hpp) as one JSON object, every key saying its unit:
// angles in degrees, shares in percent, distances in the input's units and in percent of its
// bounding-box diagonal.
VOROCRUST_API std::string surface_quality_json(const SurfaceQuality& quality, int indent = 2);

// The volume-quality figures (cell_quality.hpp) as one JSON object: count, aspect ratio (min,
// mean, max, the worst cell and its seed, the histogram with its overflow), volume, face count,
// shortest relative edge. Totals over the cells, not the per-cell list. An infinite aspect ratio
// (a cell without interior) is written as null, JSON having no infinity.
VOROCRUST_API std::string cell_quality_json(const CellQuality& quality, int indent = 2);

// What `vorocrust quality OUTDIR --json` prints: the surface figures as surface_quality_json
// gives them, at the top level, when the surface was measured, and the cell figures under
// "cells" when the cells were. At least one of the two.
VOROCRUST_API std::string quality_json(const SurfaceQuality* surface, const CellQuality* cells, int indent = 2);

// What OUTDIR/report.json holds after one `cells` run.
struct VOROCRUST_API CellsReport {
  std::vector<std::string> command;  // argv as given
  std::string seeds_file;
  std::size_t seeds = 0;
  const VoronoiMesh* mesh = nullptr;
  const CellQuality* quality = nullptr;
  std::vector<PhaseTiming> timings;  // as RunReport's
  std::string previous;  // the text of OUTDIR/report.json before the run; empty if none
};

// In a folder without a mesh run's report: {"vorocrust_version", "command", "seeds_file",
// "seeds", "status": "ok", "timings", "total_seconds", "cells"}, where "cells" is {"cells",
// "faces", "interior_faces", "boundary_faces", "points", "volume", "quality":
// cell_quality_json}. When `previous` is a mesh run's report (a JSON object naming its
// "inputs"), that report with only its "cells" object replaced by this run's, which then also
// names "seeds_file", "command" and "timings" of the rebuild: the run's inputs, options and
// surface figures stay, so `vorocrust quality OUTDIR` still finds the model.
VOROCRUST_API std::string cells_report_json(const CellsReport& report, int indent = 2);

// The option table (options.hpp) as one JSON list, an object per option: name, kind, label, help,
// section, unit, group, default (null: unset), min, max (null: unbounded), min_open, max_open,
// also, also_means, choices, unset_means, plain_default, smooth_default, unset_number,
// front_ends, the spellings of each front end (python, cli, meshlab, freecad, label), and
// default_text and range_text. Texts that name other options name them as `spelling` spells
// them. What `vorocrust options --json` prints and the Python module's OPTIONS hold.
VOROCRUST_API std::string options_json(Spelling spelling, int indent = 2);

// What a run says about itself, a line each, as every front end shows it (run_job's summary):
// the balls and features, the surface and its figures, the cells and theirs, as far as the run
// went.
VOROCRUST_API std::vector<std::string> run_summary(const MeshResult& result, const MeshOptions& options);
// What the run changed in its input that the user should know: self-intersections cut, smoothing
// rounds refused.
VOROCRUST_API std::vector<std::string> run_warnings(const MeshResult& result);
// How orthogonal the faces are to their seed links, and checkMesh's figures against the cell
// centroids, in one line, so that the two are never confused.
VOROCRUST_API std::string face_figures_line(const CellQuality& quality);
// "wrote FOLDER/mesh.vtu (open it in ParaView)" and the like, for the volume formats among
// `formats`.
VOROCRUST_API std::vector<std::string> written_lines(const std::filesystem::path& folder, const std::vector<OutputFormat>& formats);

}  // namespace vorocrust
