// The `mesh2d` subcommand: a 2D domain meshed through run_plane_job (vorocrust/plane.hpp).
#pragma once

#include <string>
#include <vector>

#include "table_options.hpp"

namespace CLI {
class App;
}

namespace vorocrust::cli {

struct Mesh2dArgs {
  std::string input;
  std::string output_dir;
  TableOptions options;
  std::vector<std::string> formats;
  double thickness = 1;
  bool quiet = false;
  std::vector<std::string> command_line;
};

CLI::App* add_mesh2d_command(CLI::App& app, Mesh2dArgs& args);
int run_mesh2d(const Mesh2dArgs& args);

}  // namespace vorocrust::cli
