#include <cstdio>
#include <filesystem>
#include <optional>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "vorocrust/vorocrust.hpp"

namespace vorocrust::cli {

namespace {

std::vector<std::filesystem::path> as_paths(const std::vector<std::string>& inputs) {
  return {inputs.begin(), inputs.end()};
}

void print_text(const SurfaceMesh& mesh, const MeshInfo& info, const ValidationReport& validation,
                const std::optional<std::vector<RegionSummary>>& regions, const std::vector<std::string>& inputs) {
  std::printf("input              ");
  for (std::size_t i = 0; i < inputs.size(); ++i) std::printf("%s%s", i ? ", " : "", inputs[i].c_str());
  std::printf("\nvertices           %zu\nfaces              %zu\nedges              %zu\n", info.vertices, info.faces,
              info.edges);
  std::printf("components         %zu\nboundary edges     %zu\nnon-manifold edges %zu\n", info.components.size(),
              info.boundary_edges, info.non_manifold_edges);
  if (info.genus) {
    std::printf("genus              %d\n", *info.genus);
  } else {
    std::printf("genus              undefined (not every component is closed and manifold)\n");
  }
  const auto& box = info.bounding_box;
  std::printf("bounding box       [%g, %g, %g] .. [%g, %g, %g], diagonal %g\n", box.min().x(), box.min().y(),
              box.min().z(), box.max().x(), box.max().y(), box.max().z(), box.diagonal().norm());
  std::printf("area               %g\n", info.area);
  std::printf("groups             %zu\n", info.groups.size());
  for (const GroupInfo& g : info.groups) std::printf("  %-24s %zu faces\n", g.name.c_str(), g.faces);
  if (regions) {
    std::printf("regions            %zu (label 0 outside)\n", regions->size());
    for (std::size_t r = 0; r < regions->size(); ++r) {
      const RegionSummary& s = (*regions)[r];
      std::printf("  %zu %-22s %zu piece%s", r, s.name.c_str(), s.pieces, s.pieces == 1 ? "" : "s");
      if (r > 0 || s.pieces > 1) std::printf(", volume %.10g", s.volume);
      std::printf("\n");
    }
  } else if (mesh.has_regions()) {
    std::printf("regions            %zu:", mesh.region_names.size());
    for (const std::string& r : mesh.region_names) std::printf(" %s", r.c_str());
    std::printf("\n");
  }
  std::printf("closed shells      ");
  bool any = false;
  for (std::size_t c = 0; c < info.components.size(); ++c) {
    const ComponentInfo& part = info.components[c];
    if (!part.volume) continue;
    std::printf("%s\n  component %zu: %zu faces, genus %d, volume %.10g", any ? "" : "", c, part.faces,
                *part.genus, *part.volume);
    any = true;
  }
  std::printf("%s\n", any ? "" : "none (volumes need closed manifold components)");
  if (validation.findings.empty()) {
    std::printf("findings           none\n");
    return;
  }
  std::printf("findings           %zu\n", validation.findings.size());
  for (const Finding& f : validation.findings) {
    std::printf("  %s [%s]: %s\n", to_string(f.severity), f.code.c_str(), f.message.c_str());
  }
}

}  // namespace

int run_info(const InfoArgs& args) {
  SurfaceMesh mesh = read_meshes(as_paths(args.inputs));
  ValidationOptions options;
  options.check_self_intersections = !args.skip_self_intersections;
  const ValidationReport validation = validate(mesh, options);
  const MeshInfo info = mesh_info(mesh);
  // The regions of space, as meshing finds them, for an input meshing accepts.
  std::optional<std::vector<RegionSummary>> regions;
  std::optional<Error> region_error;
  if (!validation.has_errors()) {
    try {
      regions = find_regions(mesh);
    } catch (const Error& e) {
      region_error = e;
    }
  }
  if (args.json) {
    std::printf("%s\n", info_json(args.inputs, mesh, info, validation).c_str());
  } else {
    print_text(mesh, info, validation, regions, args.inputs);
  }
  if (region_error) throw *region_error;
  if (validation.has_errors()) {
    std::size_t errors = 0;
    for (const Finding& f : validation.findings) errors += f.severity == Finding::Severity::Error;
    std::fprintf(stderr, "vorocrust: invalid geometry: %zu kinds of problems found, listed under findings\n", errors);
    return kInvalidGeometry;
  }
  return kOk;
}

}  // namespace vorocrust::cli
