#include <cstdio>
#include <filesystem>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "progress_display.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/job.hpp"

namespace vorocrust::cli {

int run_mesh(const MeshArgs& args) {
  Job job;
  job.inputs.assign(args.inputs.begin(), args.inputs.end());
  job.output_dir = args.output_dir;
  job.command = args.command_line;
  args.options.apply(job.options);
  const auto say = [&](const std::string& line) {
    if (!args.quiet) std::fprintf(stderr, "vorocrust: %s\n", line.c_str());
  };
  // The folder is made first, so that a run that fails says why in its report.json.
  std::error_code ec;
  std::filesystem::create_directories(job.output_dir, ec);
  if (ec || !std::filesystem::is_directory(job.output_dir)) {
    throw Error(Error::Kind::Output, "cannot create the output folder: " + (ec ? ec.message() : "not a folder"),
                {.file = args.output_dir});
  }
  ProgressDisplay progress(args.quiet);
  try {
    const JobResult result = run_job(job, progress.callback(), [&](const std::string& warning) {
      say(spell_options(warning, Spelling::Cli));
    });
    progress.finish();
    for (const std::string& line : result.summary) say(line);
    return kOk;
  } catch (...) {
    progress.finish();
    throw;
  }
}

}  // namespace vorocrust::cli
