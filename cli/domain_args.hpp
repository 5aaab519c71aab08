// The options that say what surface a run starts from (its box, its self-intersections), shared
// by `mesh`, `check-balls` and `quality`, which must start from the same surface to check that
// run's balls and measure its output surface.
#pragma once

#include <filesystem>
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

// The surface a run of `options` started from: the models read and merged, validated (orientation
// made consistent; their crossings are resolved, not refused), in their box, cut along their
// self-intersections as options.self_intersections says (prepare_domain). What `check-balls` checks
// a run's balls against and what `quality` measures its surface against.
SurfaceMesh read_domain(const std::vector<std::filesystem::path>& models, const MeshOptions& options);

// --box and --self-intersections on `command`; `refuse` only where the command can stop for
// crossing faces (`mesh`: check-balls checks balls a run made, which a refused run made none of).
void add_domain_options(CLI::App& command, DomainArgs& args, bool refuse);

}  // namespace vorocrust::cli
