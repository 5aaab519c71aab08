// `vorocrust cells SEEDS.csv -o OUTDIR`: the conforming Voronoi mesh of a seed set, such as the
// seeds.csv of a mesh run, written in the formats --format names (write_volume_mesh.hpp; the
// regions named as the report.json beside SEEDS.csv names them, when there is one), with its
// volume quality (cell_quality.hpp): OUTDIR/report.json
// (cells_report_json: the counts and the cell figures; in a mesh run's folder they replace only
// the "cells" object of its report) and the aspect-ratio histogram in OUTDIR/quality.svg; and the seeds as
// OUTDIR/seeds.csv unless they were read from there, so `vorocrust quality OUTDIR` measures the
// folder again. Prints a summary unless quiet. Returns an exit code (exit_codes.hpp); a bad seeds.csv is an Error naming its file and
// line.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "vorocrust/write_volume_mesh.hpp"

namespace vorocrust::cli {

struct CellsArgs {
  std::string seeds_file;
  std::string output_dir;
  std::vector<std::string> formats = volume_format_names();
  std::vector<std::int32_t> materials;  // empty: every label > 0
  int threads = 0;
  bool quiet = false;
  std::vector<std::string> command_line;  // argv, for report.json
};

int run_cells(const CellsArgs& args);

}  // namespace vorocrust::cli
