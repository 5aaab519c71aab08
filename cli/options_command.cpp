#include <cstdio>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "vorocrust/plane.hpp"
#include "vorocrust/report.hpp"

namespace vorocrust::cli {

int run_options(bool json) {
  if (json) {
    std::printf("%s\n", options_json(Spelling::Cli).c_str());
    return kOk;
  }
  for (const OptionSpec& spec : mesh_option_specs()) {
    if (!(spec.front_ends & kCli)) continue;
    std::string line = option_spelling(spec, Spelling::Cli);
    line.resize(std::max<std::size_t>(line.size() + 1, 26), ' ');
    std::printf("%s%s; %s%s\n", line.c_str(), spell_options(default_text(spec), Spelling::Cli).c_str(),
                spec.kind == OptionKind::Flag ? "a flag" : "range: ", spec.kind == OptionKind::Flag ? "" : range_text(spec).c_str());
  }
  // The 2D mesher takes a part of the table, read in the plane (`vorocrust mesh2d --help`).
  std::string planar;
  const std::vector<std::string_view> names = plane_option_names();
  for (std::size_t k = 0; k < names.size(); ++k) {
    planar += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + option_spelling(*find_option(names[k]), Spelling::Cli);
  }
  std::printf("\nvorocrust mesh2d takes %s, and its own --thickness and --format.\n", planar.c_str());
  return kOk;
}

}  // namespace vorocrust::cli
