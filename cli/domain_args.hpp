// The options that say what surface a run starts from (its box, its self-intersections), shared
// by `mesh` and `check-balls`, which must start from the same surface to check that run's balls.
#pragma once

#include <string>
#include <vector>

#include "vorocrust/mesher.hpp"

namespace CLI {
class App;
}

namespace vorocrust::cli {

struct DomainArgs {
  std::string self_intersections = "resolve";  // "resolve", "refuse" or "keep"
  std::vector<double> box;                     // empty, or xmin ymin zmin xmax ymax zmax

  // Sets options.box and options.self_intersections.
  void apply(MeshOptions& options) const;
};

// --box and --self-intersections on `command`.
void add_domain_options(CLI::App& command, DomainArgs& args);

}  // namespace vorocrust::cli
