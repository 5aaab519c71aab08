#include "vorocrust/report.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/memory.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/plane.hpp"
#include "vorocrust/regions.hpp"
#include "vorocrust/version.hpp"

namespace vorocrust {

namespace {

using nlohmann::json;

json finding_json(const Finding& f) {
  json pairs = json::array();
  for (const auto& [a, b] : f.face_pairs) pairs.push_back({a, b});
  return {{"severity", to_string(f.severity)}, {"code", f.code},   {"message", f.message},
          {"count", f.count},                  {"faces", f.faces}, {"face_pairs", pairs}};
}

json info_object(const std::vector<std::string>& inputs, const SurfaceMesh& mesh, const MeshInfo& info,
                 const ValidationReport& validation) {
  json components = json::array();
  json volumes = json::array();
  for (const ComponentInfo& c : info.components) {
    components.push_back({{"faces", c.faces},
                          {"vertices", c.vertices},
                          {"edges", c.edges},
                          {"boundary_edges", c.boundary_edges},
                          {"non_manifold_edges", c.non_manifold_edges},
                          {"closed", c.closed()},
                          {"manifold", c.manifold()},
                          {"genus", c.genus ? json(*c.genus) : json(nullptr)},
                          {"volume", c.volume ? json(*c.volume) : json(nullptr)},
                          {"area", c.area}});
    if (c.volume) volumes.push_back(*c.volume);
  }
  json groups = json::array();
  for (const GroupInfo& g : info.groups) groups.push_back({{"name", g.name}, {"source", g.source_file}, {"faces", g.faces}});
  json findings = json::array();
  for (const Finding& f : validation.findings) findings.push_back(finding_json(f));
  const auto& box = info.bounding_box;
  return {{"inputs", inputs},
          {"vertices", info.vertices},
          {"faces", info.faces},
          {"edges", info.edges},
          {"boundary_edges", info.boundary_edges},
          {"non_manifold_edges", info.non_manifold_edges},
          {"components", info.components.size()},
          {"component_details", components},
          {"genus", info.genus ? json(*info.genus) : json(nullptr)},
          {"groups", groups},
          {"regions", mesh.region_names},
          {"bounding_box",
           {{"min", {box.min().x(), box.min().y(), box.min().z()}},
            {"max", {box.max().x(), box.max().y(), box.max().z()}},
            {"diagonal", box.diagonal().norm()}}},
          {"area", info.area},
          {"shell_volumes", volumes},
          {"findings", findings},
          {"valid", !validation.has_errors()}};
}

// Per label: its name, how many connected pieces of space carry it, the faces' sides facing
// them and the bounded pieces' volume.
json regions_object(const std::vector<RegionSummary>& regions) {
  json list = json::array();
  for (std::size_t r = 0; r < regions.size(); ++r) {
    list.push_back({{"label", r}, {"name", regions[r].name}, {"pieces", regions[r].pieces},
                    {"sides", regions[r].sides}, {"volume", regions[r].volume}});
  }
  return list;
}

json topology_object(const SurfaceTopology& t) {
  return {{"components", t.components},
          {"euler_characteristic", t.euler_characteristic},
          {"closed", t.closed},
          {"boundary_edges", t.boundary_edges},
          {"non_manifold_edges", t.non_manifold_edges}};
}

json optional_number(const std::optional<double>& x) { return x ? json(*x) : json(nullptr); }

// The volume the surfaces enclose, and each region's.
json enclosed_volume_object(const SurfaceQuality& q) {
  json regions = json::array();
  for (const RegionVolume& r : q.region_volumes) {
    regions.push_back({{"name", r.name},
                       {"input", optional_number(r.input)},
                       {"output", optional_number(r.output)},
                       {"percent_change", optional_number(r.change_percent())}});
  }
  return {{"input", optional_number(q.input_volume)},
          {"output", optional_number(q.output_volume)},
          {"percent_change", optional_number(q.volume_change_percent())},
          {"regions", regions}};
}

// The paper's section 3 figures: angle bounds and shares, minimum triangle quality, the
// Hausdorff distance relative to the bounding-box diagonal; with the counts behind them.
json quality_object(const SurfaceQuality& q) {
  return {{"triangles", q.triangles},
          {"angles",
           {{"min_degrees", q.min_angle_degrees},
            {"max_degrees", q.max_angle_degrees},
            {"percent_below_30_degrees", q.percent_angles_below_30},
            {"percent_above_90_degrees", q.percent_angles_above_90}}},
          {"triangle_quality",
           {{"definition", "6 area / (sqrt(3) longest_edge half_perimeter); 1 for the equilateral triangle"},
            {"min", q.min_quality},
            {"mean", q.mean_quality},
            {"histogram", {{"low", 0.0}, {"high", 1.0}, {"counts", q.quality_histogram}}}}},
          {"hausdorff",
           {{"distance", q.hausdorff},
            {"percent_of_bounding_box_diagonal", 100.0 * q.hausdorff_relative},
            {"input_to_output", q.input_to_output},
            {"output_to_input", q.output_to_input},
            {"bounding_box_diagonal", q.bounding_box_diagonal},
            {"input_samples", q.input_samples},
            {"output_samples", q.output_samples}}},
          {"enclosed_volume", enclosed_volume_object(q)},
          {"topology",
           {{"matches", q.topology_matches},
            {"input", topology_object(q.input_topology)},
            {"output", topology_object(q.output_topology)}}}};
}

// A figure that may be infinite (a cell without interior): null then, JSON having no infinity.
json finite_or_null(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

json distribution_object(const PartDistribution& d) {
  json below = json::array();
  for (std::size_t k = 0; k < d.thresholds.size(); ++k) {
    below.push_back({{"below", d.thresholds[k]}, {"count", d.below[k]}, {"percent", d.percent_below(k)}});
  }
  return {{"count", d.count},
          {"min", d.min},
          {"mean", d.mean},
          {"max", d.max},
          {"min_cell", d.min_cell},
          {"thresholds", below},
          {"histogram", {{"low", d.low}, {"high", d.high}, {"counts", d.histogram}, {"above_high", d.above_high}}}};
}

// One measure of the cells' parts, by layer.
json layers_object(const CellQuality& q, const char* definition, PartDistribution LayerParts::*measure) {
  return {{"definition", definition},
          {"boundary_layer", distribution_object(q.boundary_layer.*measure)},
          {"interior", distribution_object(q.interior.*measure)}};
}

// The paper's section 3 volume figure, the maximum aspect ratio, with its distribution and the
// other per-cell measures.
json cell_quality_object(const CellQuality& q) {
  return {{"cells", q.cells.size()},
          {"aspect_ratio",
           {{"definition",
             "radius of the smallest enclosing sphere / radius of the largest inscribed ball; sqrt(3) for a cube"},
            {"min", finite_or_null(q.min_aspect_ratio)},
            {"mean", finite_or_null(q.mean_aspect_ratio)},
            {"max", finite_or_null(q.max_aspect_ratio)},
            {"worst_cell", q.worst_cell},
            {"worst_seed", q.worst_seed},
            {"histogram",
             {{"low", q.histogram_low},
              {"high", q.histogram_high},
              {"counts", q.aspect_ratio_histogram},
              {"above_high", q.aspect_ratio_above_high}}}}},
          {"volume", {{"min", q.min_volume}, {"max", q.max_volume}, {"total", q.total_volume}}},
          {"faces", {{"min", q.min_faces}, {"mean", q.mean_faces}, {"max", q.max_faces}}},
          {"shortest_edge",
           {{"definition", "shortest edge / cube root of the cell volume; 1 for a cube"},
            {"min", q.min_shortest_edge_relative},
            {"mean", q.mean_shortest_edge_relative},
            {"cell", q.shortest_edge_cell}}},
          {"layers",
           {{"definition",
             "boundary_layer: cells of surface and cap seeds (on protecting spheres), of repair seeds (splitting the "
             "cells beside them) and cells with a face to no "
             "cell or to another material's cell; interior: the others"},
            {"boundary_layer_cells", q.boundary_layer.cells},
            {"interior_cells", q.interior.cells}}},
          {"edge_length",
           layers_object(q, "each edge of each cell / cube root of that cell's volume", &LayerParts::edge_length)},
          {"face_area",
           layers_object(q, "each face of each cell / the cube root of that cell's volume, squared",
                         &LayerParts::face_area)},
          {"dihedral_angle",
           layers_object(q, "degrees inside each cell between the two faces at each of its edges",
                         &LayerParts::dihedral_angle)},
          {"skewness",
           {{"definition", "checkMesh's face skewness; above 4 it calls a face highly skew"},
            {"max", q.max_skewness},
            {"face", q.most_skew_face},
            {"highly_skew_faces", q.highly_skew_faces}}},
          {"link_angle",
           {{"definition",
             "degrees between a face between two cells and the link between their seeds; 0 for Voronoi faces up to "
             "rounding"},
            {"max", q.max_link_angle},
            {"face", q.link_angle_face}}},
          {"non_orthogonality",
           {{"definition",
             "checkMesh's: degrees between a face between two cells and the link between their centroids"},
            {"max", q.max_non_orthogonality},
            {"mean", q.mean_non_orthogonality}}}};
}

// The counts of a Voronoi mesh, with its quality when measured.
json cells_object(const VoronoiMesh& mesh, const CellQuality* quality) {
  const std::size_t interior = count_interior_faces(mesh);
  const double volume = total_volume(mesh);
  json doc = {{"cells", mesh.cells.size()},         {"faces", mesh.faces.size()},
              {"interior_faces", interior},         {"boundary_faces", mesh.faces.size() - interior},
              {"interface_faces", count_interface_faces(mesh)},
              {"points", mesh.points.size()},       {"volume", volume}};
  if (quality) doc["quality"] = cell_quality_object(*quality);
  return doc;
}

// The output triangles by what they separate. A conforming mesh has one boundary face per
// "boundary" triangle (a meshed region against one that is not) and one interface face per
// "interface" triangle (two meshed regions); a "sheet" (one region on both sides) lies inside
// the cells of its region, cut into as many faces as its seeds make.
json triangle_sides_object(const SurfaceMesh& surface, const std::vector<bool>& meshed) {
  std::size_t boundary = 0, interface = 0, sheet = 0, unmeshed = 0;
  const auto is_meshed = [&](std::int32_t label) {
    return label >= 0 && static_cast<std::size_t>(label) < meshed.size() && meshed[label];
  };
  for (const RegionPair& sides : surface.face_regions) {
    if (sides.back == sides.front) ++sheet;
    else if (is_meshed(sides.back) && is_meshed(sides.front)) ++interface;
    else if (is_meshed(sides.back) || is_meshed(sides.front)) ++boundary;
    else ++unmeshed;
  }
  return {{"boundary", boundary}, {"interface", interface}, {"sheet", sheet}, {"unmeshed", unmeshed}};
}

// Timings as a list of {phase, seconds, runs, peak_resident_bytes}, one entry per phase in the
// order phases first ran, and their sum. A phase that runs many times (the refinement's passes,
// "refinement: patches, pass 12"; the skew repair's rounds) is one entry: a list of every run was
// hundreds long. peak_resident_bytes is the process's peak by the phase's last end.
std::pair<json, double> timings_object(const std::vector<PhaseTiming>& timings) {
  json list = json::array();
  std::map<std::string, std::size_t, std::less<>> entry_of;
  double total = 0;
  for (const PhaseTiming& t : timings) {
    const std::string phase = t.name.substr(0, t.name.find(", pass "));
    const auto [at, fresh] = entry_of.try_emplace(phase, list.size());
    if (fresh) list.push_back({{"phase", phase}, {"seconds", 0.0}, {"runs", 0}, {"peak_resident_bytes", 0}});
    json& entry = list[at->second];
    entry["seconds"] = entry["seconds"].get<double>() + t.seconds;
    entry["runs"] = entry["runs"].get<int>() + 1;
    entry["peak_resident_bytes"] = std::max(entry["peak_resident_bytes"].get<std::size_t>(), t.peak_resident_bytes);
    total += t.seconds;
  }
  return {list, total};
}

// The options in force, by their table names; a quantity with a unit has it in its key
// ("sharp_angle_degrees"), and an option unset without a default is null.
json options_object(const MeshOptions& options) {
  json doc = json::object();
  for (const auto& [name, value] : options_in_force(options)) {
    const OptionSpec& spec = *find_option(name);
    std::string key(name);
    if (!spec.unit.empty()) {
      key += '_';
      key += spec.unit;
    }
    doc[key] = std::visit(
        [](const auto& v) -> json {
          if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::monostate>) {
            return nullptr;
          } else {
            return v;
          }
        },
        value);
  }
  return doc;
}

}  // namespace

std::string options_json(Spelling spelling, int indent) {
  static const char* const kKinds[] = {"flag", "integer", "real", "choice", "choices", "file", "box"};
  const auto number_or_null = [](const std::optional<double>& x) { return x && std::isfinite(*x) ? json(*x) : json(nullptr); };
  json list = json::array();
  const std::vector<std::string_view> plane = plane_option_names();
  for (const OptionSpec& spec : mesh_option_specs()) {
    json front_ends = json::array();
    for (const auto& [bit, name] : {std::pair{kCli, "cli"}, {kPython, "python"}, {kMeshLab, "meshlab"}, {kFreeCad, "freecad"}}) {
      if (spec.front_ends & bit) front_ends.push_back(name);
    }
    json choices = json::array();
    for (std::string_view c : spec.choices) choices.push_back(c);
    json value = std::visit(
        [](const auto& v) -> json {
          if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::monostate>) {
            return nullptr;
          } else {
            return v;
          }
        },
        spec.default_value);
    list.push_back({{"name", spec.name},
                    {"kind", kKinds[static_cast<int>(spec.kind)]},
                    {"label", spec.label},
                    {"help", spell_options(std::string(spec.help), spelling)},
                    {"section", spec.section},
                    {"unit", spec.unit},
                    {"group", spec.group},
                    {"default", value},
                    {"min", number_or_null(spec.min)},
                    {"max", number_or_null(spec.max)},
                    {"min_open", spec.min_open},
                    {"max_open", spec.max_open},
                    {"also", number_or_null(spec.also)},
                    {"also_means", spec.also_means},
                    {"choices", choices},
                    {"unset_means", spec.unset_means},
                    {"plain_default", number_or_null(spec.plain_default)},
                    {"smooth_default", number_or_null(spec.smooth_default)},
                    {"unset_number", number_or_null(spec.unset_number)},
                    {"front_ends", front_ends},
                    {"mesh2d", std::ranges::find(plane, spec.name) != plane.end()},
                    {"python", option_spelling(spec, Spelling::Python)},
                    {"cli", option_spelling(spec, Spelling::Cli)},
                    {"meshlab", option_spelling(spec, Spelling::MeshLab)},
                    {"freecad", option_spelling(spec, Spelling::FreeCad)},
                    {"default_text", spell_options(default_text(spec), spelling)},
                    {"range_text", range_text(spec)}});
  }
  return list.dump(indent);
}

std::string info_json(const std::vector<std::string>& inputs, const SurfaceMesh& mesh, const MeshInfo& info,
                      const ValidationReport& validation, int indent) {
  json doc = info_object(inputs, mesh, info, validation);
  if (!validation.has_errors()) {
    try {
      doc["region_details"] = regions_object(find_regions(mesh));
    } catch (const Error& e) {
      doc["region_error"] = e.what();
    }
  }
  return doc.dump(indent);
}

std::string run_report_json(const RunReport& report, int indent) {
  const auto [timings, total] = timings_object(report.timings);
  json doc = {{"vorocrust_version", VOROCRUST_VERSION},
              {"command", report.command},
              {"inputs", report.inputs},
              {"options", options_object(report.options)},
              {"status", report.status},
              {"message", report.message},
              {"timings", timings},
              {"total_seconds", total}};
  if (report.result) {
    doc["regions"] = regions_object(report.result->regions);
    const SelfIntersectionStats& s = report.result->self_intersections;
    doc["self_intersections"] = {{"face_pairs", s.face_pairs},     {"faces_cut", s.faces_cut},
                                 {"points_added", s.points_added}, {"faces_dropped", s.faces_dropped},
                                 {"faces", s.faces}};
    const FeatureCounts& f = report.result->features;
    const RefinementStats& r = report.result->refinement;
    doc["features"] = {{"sharp_edges", f.sharp_edges}, {"corners", f.corners},  {"creases", f.creases},
                       {"patches", f.patches},         {"faces_after_smoothing", f.faces_after_smoothing},
                       {"smoothing_iterations", f.smoothing_iterations},
                       {"smoothing_bounding_rounds", f.smoothing_bounding_rounds},
                       {"smoothing_largest_offset", f.smoothing_largest_offset},
                       {"smoothing_rounds_refused", f.smoothing_rounds_refused},
                       {"smoothing_faces_unfolded", f.smoothing_faces_unfolded},
                       {"smoothing_rounds_crossing", f.smoothing_rounds_crossing}};
    // The rows of the paper's Table 1, with the counts behind them.
    doc["refinement"] = {
        {"balls", {{"corner", r.balls[0]}, {"crease", r.balls[1]}, {"patch", r.balls[2]},
                   {"total", r.balls[0] + r.balls[1] + r.balls[2]}}},
        {"seconds",
         {{"boundary_samples", r.setup_seconds},
          {"corner_protection", r.phase_seconds[0]},
          {"edge_protection", r.phase_seconds[1]},
          {"surface_coverage", r.phase_seconds[2]},
          {"fixing_c3_violations", r.c3_seconds},
          {"c1_c2_sweep", r.sweep_seconds}}},
        {"darts", r.darts},
        {"rejected_for_density", r.rejected_for_density},
        {"subdivisions", r.subdivisions},
        {"largest_pool", r.largest_pool},
        {"c1_shrinks", r.c1_shrinks},
        {"c3_shrinks", r.c3_shrinks},
        {"sliver_shrinks", r.sliver_shrinks},
        {"skinny_triangle_shrinks", r.skinny_triangle_shrinks},
        {"rounds", r.rounds},
        {"boundary_samples", r.boundary_samples},
        {"bare_at_deepest", {{"pieces", r.bare_pieces}, {"crease_length", r.bare_measure[0]}, {"patch_area", r.bare_measure[1]}}},
        {"converged", r.converged}};
  }
  if (report.result && !report.result->slivers.iterations.empty()) {
    const MeshResult& m = *report.result;
    // Paper Figure 9: per iteration, the share of triplets with a half-covered seed pair and the
    // largest shrinkage ratio applied to remove them.
    json rounds = json::array();
    for (const SliverIteration& it : m.slivers.iterations) {
      rounds.push_back({{"shrunk_for", it.shrunk == SliverIteration::Shrunk::ForSlivers           ? "slivers"
                                       : it.shrunk == SliverIteration::Shrunk::ForSkinnyTriangles ? "skinny_triangles"
                                       : it.shrunk == SliverIteration::Shrunk::ForNearTwins       ? "near_twins"
                                                                                                  : "nothing"},
                        {"balls", it.balls},
                        {"triplets", it.triplets},
                        {"half_covered", it.half_covered},
                        {"half_covered_percent", it.triplets ? 100.0 * it.half_covered / it.triplets : 0.0},
                        {"balls_shrunk", it.balls_shrunk},
                        {"max_shrinkage_ratio", it.max_shrinkage_ratio},
                        {"skinny_triangles", it.skinny_triangles},
                        {"near_twins", it.near_twins},
                        {"seconds", it.seconds}});
    }
    doc["slivers"] = {{"iterations", m.slivers.rounds()},
                      {"half_covered_left", m.slivers.iterations.back().half_covered},
                      {"safe_mode", m.slivers.safe_mode},
                      {"sliver_rounds", m.slivers.rounds_for(SliverIteration::Shrunk::ForSlivers)},
                      {"skinny_triangle_rounds", m.slivers.rounds_for(SliverIteration::Shrunk::ForSkinnyTriangles)},
                      {"skinny_triangles_left", m.slivers.iterations.back().skinny_triangles},
                      {"near_twin_rounds", m.slivers.rounds_for(SliverIteration::Shrunk::ForNearTwins)},
                      {"near_twins_left", m.slivers.iterations.back().near_twins},
                      {"per_iteration", rounds}};
  }
  // The output surface: the surface seeds' (or, for clipped cells, the input's own).
  if (report.result && report.result->surface.num_faces() > 0) {
    const MeshResult& m = *report.result;
    std::size_t surface_seeds = 0;
    for (const Seed& seed : m.seeds) surface_seeds += seed.kind == SeedKind::Surface;
    doc["surface"] = {{"surface_seeds", surface_seeds},
                      {"vertices", m.surface.num_vertices()},
                      {"triangles", m.surface.num_faces()},
                      {"regions", m.surface.region_names}};
    // Before the cells, every region but the outside (label 0) is taken as meshed.
    std::vector<bool> meshed(m.surface.region_names.size(), m.cells.cells.empty());
    if (!meshed.empty()) meshed[0] = false;
    for (const VoronoiCell& cell : m.cells.cells) {
      if (static_cast<std::size_t>(cell.region) < meshed.size()) meshed[cell.region] = true;
    }
    if (m.surface.has_regions()) doc["surface"]["triangles_by_sides"] = triangle_sides_object(m.surface, meshed);
    if (m.surface_quality) doc["surface"]["quality"] = quality_object(*m.surface_quality);
  }
  if (report.result && !report.result->cells.cells.empty()) {
    const MeshResult& m = *report.result;
    const InteriorStats& i = m.interior;
    doc["interior"] = {{"interior_seeds", i.interior_seeds}, {"outside_seeds", i.outside_seeds},
                       {"darts", i.darts},                   {"spokes", i.spokes},
                       {"spoke_seeds", i.spoke_seeds},       {"lattice_seeds", i.lattice_seeds},
                       {"lipschitz_shrinks", i.lipschitz_shrinks}, {"rounds", i.rounds},
                       {"cvt_iterations", i.cvt_iterations}, {"cvt_last_move", i.cvt_last_move},
                       {"cap_seeds", i.cap_seeds},           {"split_seeds", i.split_seeds},
                       {"repair_seeds", i.repair_seeds},
                       {"repair_rounds", i.repair_rounds},
                       {"aspect_split_seeds", i.aspect_split_seeds},
                       {"aspect_split_rounds", i.aspect_split_rounds},
                       {"aspect_split_rounds_undone", i.aspect_split_rounds_undone}};
    doc["memory"] = {{"resident_bytes_before_cells", i.resident_bytes_before_cells},
                     {"estimated_peak_bytes", i.estimated_peak_bytes},
                     {"peak_resident_bytes", peak_resident_bytes()}};
    doc["cells"] = cells_object(m.cells, m.cell_quality ? &*m.cell_quality : nullptr);
    if (m.clipping) {
      const ClippingStats& c = *m.clipping;
      doc["clipping"] = {{"clipped_cells", c.clipped_cells},   {"surface_pieces", c.surface_pieces},
                         {"clipped_faces", c.clipped_faces},   {"dropped_faces", c.dropped_faces},
                         {"holes", c.holes}};
      if (report.options.sliver_angle > 0) {
        const SliverPerturbation& s = c.slivers;
        doc["clipping"]["sliver_perturbation"] = {
            {"rounds", s.rounds},           {"slivers_before", s.slivers_before}, {"slivers_after", s.slivers_after},
            {"moves_tried", s.moves_tried}, {"moves_kept", s.moves_kept}};
      }
    }
    if (m.dual_tets) {
      const DualTetFigures& t = *m.dual_tets;
      doc["dual_tets"] = {{"tets", t.tets},
                          {"degenerate_points", t.degenerate_points},
                          {"volume", t.volume},
                          {"mean_min_dihedral", t.mean_min_dihedral},
                          {"min_min_dihedral", t.min_min_dihedral},
                          {"max_max_dihedral", t.max_max_dihedral},
                          {"mean_radius_ratio", t.mean_radius_ratio},
                          {"min_radius_ratio", t.min_radius_ratio},
                          {"mean_q4", t.mean_q4},
                          {"min_q4", t.min_q4},
                          {"definition",
                           "the Delaunay tetrahedra of the seeds whose circumcentre lies inside their material "
                           "(Yan et al. 2011, 5.2); dihedral angles in degrees, radius ratio 3 r_in / r_circ, "
                           "q4 = 12 (9 V^2)^(1/3) / sum of squared edge lengths (their Table 2)"}};
    }
    if (m.welding) {
      const WeldStats& w = *m.welding;
      doc["welding"] = {{"fraction", w.fraction},
                        {"short_edges", w.short_edges},
                        {"welded_points", w.welded_points},
                        {"dropped_faces", w.dropped_faces},
                        {"kept_edges", w.kept_edges},
                        {"non_planar_faces", w.non_planar_faces},
                        {"max_non_planarity", w.max_non_planarity},
                        {"non_planarity_definition",
                         "largest distance of a face's point from its plane over the face's diameter"},
                        {"shortest_edge_before", w.shortest_edge_before},
                        {"shortest_edge_after", w.shortest_edge_after},
                        {"shortest_edge_definition", "shortest edge over the seeds' radius"}};
    }
  }
  if (report.mesh && report.input && report.validation) {
    doc["input"] = info_object(report.inputs, *report.mesh, *report.input, *report.validation);
  }
  return doc.dump(indent);
}

std::vector<std::string> run_report_regions(const std::filesystem::path& report_json) {
  std::ifstream in(report_json, std::ios::binary);
  if (!in) return {};
  std::stringstream text;
  text << in.rdbuf();
  const json doc = json::parse(text.str(), nullptr, false);
  if (!doc.is_object() || !doc.contains("surface") || !doc["surface"].is_object()) return {};
  const json& regions = doc["surface"].value("regions", json());
  std::vector<std::string> names;
  if (!regions.is_array()) return {};
  for (const json& name : regions) {
    if (!name.is_string()) return {};
    names.push_back(name.get<std::string>());
  }
  return names;
}

namespace {

[[noreturn]] void fail_on_report(const std::filesystem::path& report_json, const std::string& why) {
  throw Error(Error::Kind::UnreadableInput, why, {.file = report_json.string()});
}

// An OUTDIR/report.json read whole; Error(UnreadableInput) naming it when it cannot be.
json read_run_report(const std::filesystem::path& report_json) {
  std::ifstream in(report_json, std::ios::binary);
  if (!in) fail_on_report(report_json, std::filesystem::exists(report_json) ? "cannot open" : "cannot open: no such file");
  std::stringstream text;
  text << in.rdbuf();
  json doc = json::parse(text.str(), nullptr, false);
  if (doc.is_discarded()) fail_on_report(report_json, "not a JSON document");
  return doc;
}

}  // namespace

MeshOptions run_report_domain(const std::filesystem::path& report_json) {
  const json doc = read_run_report(report_json);
  MeshOptions options;
  if (!doc.is_object() || !doc.contains("options") || !doc["options"].is_object()) return options;
  const json& o = doc["options"];
  if (const auto box = o.find("box"); box != o.end() && !box->is_null()) {
    if (!box->is_array() || box->size() != 6 ||
        !std::all_of(box->begin(), box->end(), [](const json& x) { return x.is_number(); })) {
      fail_on_report(report_json, "'options.box' is not a list of six numbers");
    }
    options.box = std::array<double, 6>{};
    for (std::size_t k = 0; k < 6; ++k) (*options.box)[k] = (*box)[k].get<double>();
  }
  if (const auto mode = o.find("self_intersections"); mode != o.end()) {
    const std::optional<SelfIntersections> parsed =
        mode->is_string() ? parse_self_intersections(mode->get<std::string>()) : std::nullopt;
    if (!parsed) fail_on_report(report_json, "'options.self_intersections' is not resolve, refuse or keep");
    options.self_intersections = *parsed;
  }
  return options;
}

std::vector<std::string> run_report_inputs(const std::filesystem::path& report_json) {
  const auto fail = [&](const std::string& why) { fail_on_report(report_json, why); };
  const json doc = read_run_report(report_json);
  const auto inputs = doc.find("inputs");
  if (!doc.is_object() || inputs == doc.end() || !inputs->is_array() || inputs->empty()) {
    fail("no 'inputs' list of model files");
  }
  std::vector<std::string> paths;
  for (const json& path : *inputs) {
    if (!path.is_string()) fail("'inputs' holds something other than file names");
    paths.push_back(path.get<std::string>());
  }
  return paths;
}

std::string surface_quality_json(const SurfaceQuality& quality, int indent) { return quality_object(quality).dump(indent); }

std::string cell_quality_json(const CellQuality& quality, int indent) {
  return cell_quality_object(quality).dump(indent);
}

std::string quality_json(const SurfaceQuality* surface, const CellQuality* cells, int indent) {
  json doc = surface ? quality_object(*surface) : json::object();
  if (cells) doc["cells"] = cell_quality_object(*cells);
  return doc.dump(indent);
}

std::string cells_report_json(const CellsReport& report, int indent) {
  const auto [timings, total] = timings_object(report.timings);
  json cells = report.mesh ? cells_object(*report.mesh, report.quality) : json::object();
  json previous = report.previous.empty() ? json() : json::parse(report.previous, nullptr, false);
  if (previous.is_object() && previous.contains("inputs")) {
    cells["seeds_file"] = report.seeds_file;
    cells["command"] = report.command;
    cells["timings"] = timings;
    previous["cells"] = cells;
    return previous.dump(indent);
  }
  json doc = {{"vorocrust_version", VOROCRUST_VERSION},
              {"command", report.command},
              {"seeds_file", report.seeds_file},
              {"seeds", report.seeds},
              {"status", "ok"},
              {"timings", timings},
              {"total_seconds", total}};
  if (report.mesh) doc["cells"] = cells;
  return doc.dump(indent);
}

}  // namespace vorocrust
