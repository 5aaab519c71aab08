// The options that say what surface a run starts from (its box, its self-intersections), shared
// by `check-balls` and `quality`, which must start from the same surface as the run whose balls
// they check and whose surface they measure.
#pragma once

#include <filesystem>
#include <vector>

#include "table_options.hpp"
#include "vorocrust/mesher.hpp"

namespace vorocrust::cli {

struct DomainArgs {
  TableOptions options;  // box and self_intersections, from the library's table

  bool given() const { return options.given("box") || options.given("self_intersections"); }
  // Sets options.box and options.self_intersections as given; throws Error(Usage) for 'refuse',
  // which made no run whose balls or surface there would be to check.
  void apply(MeshOptions& options) const;
};

// The surface a run of `options` started from: the models read and merged, validated (orientation
// made consistent; their crossings are resolved, not refused), in their box, cut along their
// self-intersections as options.self_intersections says (prepare_domain). What `check-balls` checks
// a run's balls against and what `quality` measures its surface against.
SurfaceMesh read_domain(const std::vector<std::filesystem::path>& models, const MeshOptions& options);

// --box and --self-intersections on `command`.
void add_domain_options(CLI::App& command, DomainArgs& args);

}  // namespace vorocrust::cli
