// `vorocrust quality OUTDIR`: the quality figures of a mesh run (paper section 3). The surface
// figures of its output surface, OUTDIR/surface.ply, against the input it was made from, as the
// run started from it (validated, in its box, cut along its self-intersections: an input that
// cannot be so prepared is refused as `mesh` refuses it); the
// volume figures (cell_quality.hpp) of the cells of its seeds, OUTDIR/seeds.csv, rebuilt with
// compute_cells, which gives the run's own cells again (it is deterministic) without a mesh file
// to read back. Each part is measured when its file is there, at least one of them. Prints a
// short table (or JSON: quality_json) on standard output and draws the triangle-quality and
// aspect-ratio histograms in OUTDIR/quality.svg. Returns an exit code (exit_codes.hpp); a
// missing or unreadable file is an Error naming it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "domain_args.hpp"
#include "vorocrust/quality.hpp"

namespace vorocrust::cli {

struct QualityArgs {
  std::string output_dir;
  std::vector<std::string> inputs;  // empty: the `inputs` of OUTDIR/report.json
  QualityOptions options;
  // The surface the run started from, the inputs in their box and cut as the run cut them: these
  // options when given, else those OUTDIR/report.json records, else mesh's defaults.
  DomainArgs domain;
  bool json = false;
};

int run_quality(const QualityArgs& args);

}  // namespace vorocrust::cli
