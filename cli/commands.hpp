// The subcommands of the `vorocrust` program. Each returns an exit code (exit_codes.hpp) and
// leaves all algorithm work to libvorocrust.
#pragma once

#include <string>
#include <vector>

#include "domain_args.hpp"
#include "vorocrust/mesher.hpp"
#include "vorocrust/write_volume_mesh.hpp"

namespace vorocrust::cli {

struct InfoArgs {
  std::vector<std::string> inputs;
  bool json = false;
  bool skip_self_intersections = false;
};

struct MeshArgs {
  std::vector<std::string> inputs;
  std::string output_dir;
  MeshOptions options;
  bool quiet = false;
  std::string stop_after;  // "" (everything), "balls" or "surface"
  std::string interior = "random";
  DomainArgs domain;
  std::vector<std::string> formats = volume_format_names();
  std::vector<std::string> command_line;
};

int run_info(const InfoArgs& args);
int run_mesh(const MeshArgs& args);

}  // namespace vorocrust::cli
