#include "domain_args.hpp"

#include <CLI/CLI.hpp>

#include "vorocrust/read_mesh.hpp"
#include "vorocrust/validate.hpp"

namespace vorocrust::cli {

void DomainArgs::apply(MeshOptions& options) const {
  // CLI11 let through only the modes it knows.
  options.self_intersections = parse_self_intersections(self_intersections).value_or(SelfIntersections::Resolve);
  if (box.size() == 6) options.box = {box[0], box[1], box[2], box[3], box[4], box[5]};
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

void add_domain_options(CLI::App& command, DomainArgs& args, bool refuse) {
  command
      .add_option("--box", args.box,
                  "The domain around open sheets (terrains, faults, horizons): xmin ymin zmin xmax ymax zmax. "
                  "Its sides join the surface, and what no material fills inside it becomes the material "
                  "'domain', which a sheet splits. Default for an input with open edges: its bounding box "
                  "grown by a tenth of its diagonal on every side")
      ->expected(6);
  const std::string help =
      "Faces that cut through each other: 'resolve' cuts them along their intersection curves, which become creases, "
      "and joins each new piece of space to a region of the input; " +
      std::string(refuse ? "'refuse' stops with exit code 4 naming them; 'keep' meshes them as they are"
                         : "'keep' takes them as they are (as the run did)");
  const std::vector<std::string> modes =
      refuse ? std::vector<std::string>{"resolve", "refuse", "keep"} : std::vector<std::string>{"resolve", "keep"};
  command.add_option("--self-intersections", args.self_intersections, help)
      ->check(CLI::IsMember(modes))
      ->capture_default_str();
}

}  // namespace vorocrust::cli
