// `vorocrust quality`: the surface-quality figures (paper section 3) of a mesh run's output
// surface, OUTDIR/surface.ply, against the input it was made from: a short table (or JSON) on
// standard output and the triangle-quality histogram in OUTDIR/quality.svg. Returns an exit code
// (exit_codes.hpp); a missing or unreadable file is an Error naming it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "vorocrust/quality.hpp"

namespace vorocrust::cli {

struct QualityArgs {
  std::string output_dir;
  std::vector<std::string> inputs;  // empty: the `inputs` of OUTDIR/report.json
  QualityOptions options;
  bool json = false;
};

int run_quality(const QualityArgs& args);

}  // namespace vorocrust::cli
