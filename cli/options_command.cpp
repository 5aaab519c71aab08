#include <cstdio>

#include "commands.hpp"
#include "exit_codes.hpp"
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
  return kOk;
}

}  // namespace vorocrust::cli
