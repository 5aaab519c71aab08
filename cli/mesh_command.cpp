#include <cstdio>
#include <filesystem>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "progress_display.hpp"
#include "vorocrust/compare.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/job.hpp"

namespace vorocrust::cli {

namespace {

Job job_of(const MeshArgs& args) {
  Job job;
  job.inputs.assign(args.inputs.begin(), args.inputs.end());
  job.output_dir = args.output_dir;
  job.command = args.command_line;
  args.options.apply(job.options);
  // The folder is made first, so that a run that fails says why in its report.json.
  std::error_code ec;
  std::filesystem::create_directories(job.output_dir, ec);
  if (ec || !std::filesystem::is_directory(job.output_dir)) {
    throw Error(Error::Kind::Output, "cannot create the output folder: " + (ec ? ec.message() : "not a folder"),
                {.file = args.output_dir});
  }
  return job;
}

// Runs `work` with the progress shown and warnings said, unless quiet.
template <class Work>
int with_progress(const MeshArgs& args, Work&& work) {
  const auto say = [&](const std::string& line) {
    if (!args.quiet) std::fprintf(stderr, "vorocrust: %s\n", line.c_str());
  };
  ProgressDisplay progress(args.quiet);
  try {
    work(
        progress.callback(), [&](const std::string& warning) { say(spell_options(warning, Spelling::Cli)); }, say,
        [&] { progress.finish(); });
    return kOk;
  } catch (...) {
    progress.finish();
    throw;
  }
}

}  // namespace

int run_mesh(const MeshArgs& args) {
  const Job job = job_of(args);
  return with_progress(args, [&](const auto& progress, const auto& warn, const auto& say, const auto& finish) {
    const JobResult result = run_job(job, progress, warn);
    finish();
    for (const std::string& line : result.summary) say(line);
  });
}

int run_compare(const CompareArgs& args) {
  const Job job = job_of(args);
  return with_progress(args, [&](const auto& progress, const auto& warn, const auto&, const auto& finish) {
    const Comparison comparison = compare_methods(job, progress, warn);
    finish();
    std::fputs(comparison_table(comparison).c_str(), stdout);
  });
}

}  // namespace vorocrust::cli
