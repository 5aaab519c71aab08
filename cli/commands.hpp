// The subcommands of the `vorocrust` program. Each returns an exit code (exit_codes.hpp) and
// leaves all algorithm work to libvorocrust.
#pragma once

#include <string>
#include <vector>

#include "table_options.hpp"

namespace vorocrust::cli {

struct InfoArgs {
  std::vector<std::string> inputs;
  bool json = false;
  bool skip_self_intersections = false;
};

struct MeshArgs {
  std::vector<std::string> inputs;
  std::string output_dir;
  TableOptions options;  // every option of the library's table
  bool quiet = false;
  std::vector<std::string> command_line;
};

// `compare`: the mesh arguments, the method chosen by the command.
using CompareArgs = MeshArgs;

int run_info(const InfoArgs& args);
int run_compare(const CompareArgs& args);
int run_options(bool json);
int run_mesh(const MeshArgs& args);

}  // namespace vorocrust::cli
