// vorocrust/compare.hpp — VoroCrust against clipping on one model, side by side (the paper's
// section 1 and Figures 1 and 2; Ebeida and Mitchell's and Yan et al.'s clipped cells).
//
// compare_methods(job) runs `job` twice, with options.method vorocrust and then clipped, at one
// sizing: options.max_size where set; else the clipped seeds' radius is the VoroCrust cells' mean
// size (the cube root of the volume per cell), so both meshes have cells of about one size. Each
// run writes its outputs into job.output_dir/vorocrust and job.output_dir/clipped (nothing when
// output_dir is empty), and is measured by measure_method_figures against the volume the input
// encloses; job.output_dir gets compare.json (the figures) and compare.svg (each method's
// histogram of its boundary faces' shortest over longest edge). Throws what run_job throws; the
// clipped run's refusals (open sheets) included.
//
// comparison_table(comparison) is the table the front ends print: a row per figure, a column
// per method.
#pragma once

#include "vorocrust/api.hpp"

#include <string>
#include <vector>

#include "vorocrust/job.hpp"
#include "vorocrust/method_figures.hpp"
#include "vorocrust/modes.hpp"

namespace vorocrust {

struct VOROCRUST_API MethodRun {
  Method method = Method::Vorocrust;
  double max_size = 0;  // as the run was given it (infinity: unset)
  double seconds = 0;   // the mesh's phases, reading and writing left out
  MethodFigures figures;
};

struct VOROCRUST_API Comparison {
  double enclosed_volume = 0;
  std::vector<MethodRun> runs;
};

VOROCRUST_API Comparison compare_methods(const Job& job, const ProgressCallback& progress = {},
                                         const WarningCallback& warn = {});

VOROCRUST_API std::string comparison_table(const Comparison& comparison);

}  // namespace vorocrust
