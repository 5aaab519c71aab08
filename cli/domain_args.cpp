#include "domain_args.hpp"

#include "vorocrust/error.hpp"
#include "vorocrust/read_mesh.hpp"
#include "vorocrust/validate.hpp"

namespace vorocrust::cli {

void DomainArgs::apply(MeshOptions& mesh) const {
  options.apply(mesh);
  if (mesh.self_intersections == SelfIntersections::Refuse) {
    throw Error(Error::Kind::Usage,
                "self_intersections must be resolve or keep here: a run that refused its crossings made nothing to check",
                {.option = "self_intersections"});
  }
}

SurfaceMesh read_domain(const std::vector<std::filesystem::path>& models, const MeshOptions& options) {
  SurfaceMesh mesh = read_meshes(models);
  // The contract assumes consistent orientation, which validation establishes; the
  // self-intersections are resolved below as the run resolved them, so validation skips that
  // (slow) check.
  ValidationOptions validation;
  validation.check_self_intersections = false;
  (void)validate(mesh, validation);
  return prepare_domain(mesh, options);
}

void add_domain_options(CLI::App& command, DomainArgs& args) { args.options.add(command, {"box", "self_intersections"}); }

}  // namespace vorocrust::cli
