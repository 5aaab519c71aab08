// The pipeline: each stage one call, in the paper's order.
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <numbers>
#include <string>

#include "cells/conforming_cells.hpp"
#include "cells/weld_short_edges.hpp"
#include "clipping/clipped_cells.hpp"
#include "clipping/dual_tets.hpp"
#include "core/c_format.hpp"
#include "core/memory.hpp"
#include "core/phases.hpp"
#include "features/surface_features.hpp"
#include "geometry/box_tree.hpp"
#include "geometry/nearest_face.hpp"
#include "interior/interior_seeds.hpp"
#include "io/enclose_in_box.hpp"
#include "refinement/refine_balls.hpp"
#include "refinement/sizing_field.hpp"
#include "seeds/eliminate_slivers.hpp"
#include "seeds/locate_regions.hpp"
#include "seeds/surface_seeds.hpp"
#include "vorocrust/cell_quality.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/mesher.hpp"
#include "vorocrust/quality.hpp"
#include "vorocrust/regions.hpp"

namespace vorocrust {

namespace {

// What each stage takes from the run's options.
FeatureOptions feature_options(const MeshOptions& o) {
  return {o.sharp_angle() * std::numbers::pi / 180, o.smooth, o.smoothing_rounds(), o.smoothing_tolerance};
}
RefinementOptions refinement_options(const MeshOptions& o) {
  RefinementOptions r;
  r.lipschitz = o.lipschitz;
  r.sharp_angle = o.sharp_angle() * std::numbers::pi / 180;
  r.seed = o.seed;
  return r;
}
SizingField sizing_field(const MeshOptions& o) {
  return o.sizing_file.empty() ? SizingField(o.max_size) : SizingField(o.max_size, o.sizing_file);
}
SliverOptions sliver_options(const MeshOptions& o) {
  SliverOptions s;
  s.min_triangle_angle_degrees = o.min_triangle_angle();
  return s;
}
InteriorSeedOptions interior_options(const MeshOptions& o) {
  return {{.mode = o.interior, .lipschitz = o.lipschitz, .seed = o.seed}, o.cvt_iterations, o.threads};
}
ConformingCellsOptions cells_options(const MeshOptions& o) {
  ConformingCellsOptions c;
  c.cells.threads = o.threads;
  c.max_aspect_ratio = o.max_aspect_ratio;
  c.max_skewness = o.max_skewness;
  return c;
}
geometry::Box bounding_box(const SurfaceMesh& mesh) {
  geometry::Box box;
  for (const Point& p : mesh.vertices) box.include(p);
  return box;
}

// The cells are the run's largest stage, and their assembly its peak: a cell's cut polyhedron,
// its vertices' welding, its faces over the welded points and in the assembled mesh take about
// this many bytes at once (bench/RESULTS.md, "The memory guard"), on top of what the run holds
// when the seeds are placed. The files are written a block at a time and add less.
constexpr double kCellBytes = 2500;

double material_seeds(const std::vector<Seed>& seeds) {
  return static_cast<double>(
      std::count_if(seeds.begin(), seeds.end(), [](const Seed& s) { return s.region > kOutsideRegion; }));
}

// The run's peak: what it holds now and the cells to cut. Above the bound it stops, with the
// estimate: `so_far` while the interior seeds are placed (the cells of those placed so far alone
// are too many), else once all are placed.
double refuse_above_memory(double cells, const MeshOptions& options, bool so_far) {
  const auto resident = static_cast<double>(resident_bytes());
  const double peak = resident + kCellBytes * cells;
  if (peak <= options.max_memory_gb * 1e9) return resident;
  const std::string estimate =
      so_far ? c_format(
                   "more than %.3g GB at its peak: the seeds placed so far already make %.0f cells (%.3g GB now "
                   "and about %.3g KB for each)",
                   peak / 1e9, cells, resident / 1e9, kCellBytes / 1e3)
             : c_format("about %.3g GB at its peak (%.3g GB now and about %.3g KB for each of its %.0f cells)",
                        peak / 1e9, resident / 1e9, kCellBytes / 1e3, cells);
  throw Error(Error::Kind::Usage,
              c_format("the run would need %s, above max_memory's %.3g GB: raise it, or make fewer cells (a larger "
                       "maximum size or Lipschitz constant)",
                       estimate.c_str(), options.max_memory_gb),
              {.option = "max_memory"});
}

// While the interior seeds are placed: refuses the run as soon as the cells of the seeds placed so
// far, with what the run holds, already need more than the bound. A run of far too many cells
// (a maximum size mistyped by a factor of ten) stops here, before its seeds fill the memory.
std::function<void(std::size_t)> memory_guard_while_sampling(const std::vector<Seed>& surface_seeds,
                                                             const MeshOptions& options) {
  if (std::isinf(options.max_memory_gb)) return {};
  return [surface_cells = material_seeds(surface_seeds), &options](std::size_t placed) {
    refuse_above_memory(surface_cells + static_cast<double>(placed), options, true);
  };
}

// Once the seeds are placed, before the cells: the estimate goes into the report.
void guard_memory(const std::vector<Seed>& seeds, const MeshOptions& options, InteriorStats& stats) {
  const double cells = material_seeds(seeds);
  const double resident = refuse_above_memory(cells, options, false);
  stats.resident_bytes_before_cells = static_cast<std::size_t>(resident);
  stats.estimated_peak_bytes = static_cast<std::size_t>(std::llround(resident + kCellBytes * cells));
}

// Before the surface stages: the fewest cells a maximum size allows, against the memory bound
// (the machine's memory when none is given). Every point of a material lies within about
// max_size of a seed (the interior sampler is maximal at radii up to it, and the protecting balls
// are no larger), so a cell holds at most a ball of that radius, and the materials' volume needs
// at least so many cells (cgal_joint: 4.5 to 15 times fewer than it makes, from max_size 0.01 to
// 0.04). A maximum size mistyped by a factor of ten asks for a thousand times the cells; such a run
// refined for minutes and filled the memory before it failed, with a message that did not name
// max_size.
void guard_memory_for_max_size(const std::vector<RegionSummary>& regions, const MeshOptions& options) {
  if (!std::isfinite(options.max_size)) return;
  const double volume = materials_volume(regions);
  const double machine = static_cast<double>(physical_memory_bytes());
  const bool bounded = std::isfinite(options.max_memory_gb);
  const double bound = bounded ? options.max_memory_gb * 1e9 : machine;
  if (!(volume > 0) || !(bound > 0)) return;
  const double cell_volume = 4 * std::numbers::pi / 3 * std::pow(options.max_size, 3);
  const double cells = volume / cell_volume;
  if (kCellBytes * cells <= bound) return;
  const double fitting = std::cbrt(volume * kCellBytes / (4 * std::numbers::pi / 3 * bound));
  throw Error(
      Error::Kind::Usage,
      c_format("max_size %.3g asks for at least %.3g cells (the materials' volume %.4g, a ball of radius "
               "max_size at most for each), which would need at least %.3g GB at about %.3g KB for each, "
               "above %s %.3g GB: raise max_size (above %.3g for that memory)%s",
               options.max_size, cells, volume, kCellBytes * cells / 1e9, kCellBytes / 1e3,
               bounded ? "`max_memory`'s" : "this machine's", bound / 1e9, fitting, bounded ? " or `max_memory`" : ""),
      {.option = "max_size"});
}

void count_seed_kinds(const std::vector<Seed>& seeds, InteriorStats& stats) {
  for (const Seed& s : seeds) {
    stats.outside_seeds += s.kind == SeedKind::Outside;
    stats.interior_seeds += s.kind == SeedKind::Interior;
    stats.cap_seeds += s.kind == SeedKind::Cap;
    stats.split_seeds += s.kind == SeedKind::Repair;
  }
}

// The domain: the model in its box, cut along its self-intersections; the regions it bounds,
// and the fewest cells they need weighed against the memory.
SurfaceMesh labelled_domain(const SurfaceMesh& model, const MeshOptions& options, Phases& phase, MeshResult& result) {
  SurfaceMesh input =
      options.self_intersections == SelfIntersections::Resolve
          ? phase("self-intersections", [&] { return prepare_domain(model, options, &result.self_intersections); })
          : prepare_domain(model, options);
  result.regions = phase("regions", [&] { return label_regions(input); });
  guard_memory_for_max_size(result.regions, options);
  return input;
}

MeshResult run_pipeline(const SurfaceMesh& model, const MeshOptions& options, const ProgressCallback& progress) {
  MeshResult result;
  Phases phase(result.timings, progress);
  SurfaceMesh input = labelled_domain(model, options, phase, result);
  // Features (2.2), then the protecting balls (2.3).
  SurfaceFeatures features = find_features(input, feature_options(options), phase, result.features);
  result.smoothed_input = std::move(features.surface);
  const SizingField sizing = sizing_field(options);
  BallRefinement refinement(result.smoothed_input, features.strata, sizing, refinement_options(options), progress,
                            result.refinement);
  phase("refinement", [&] { refinement.run(); });
  if (options.stop_after == Stage::Balls) {
    result.balls = refinement.balls();
    return result;
  }
  // Surface seeds, slivers and the surface mesh (2.4).
  const SeedPairs pairs = phase(
      "slivers", [&] { return eliminate_slivers(refinement, sliver_options(options), progress, result.slivers); });
  result.balls = refinement.balls();
  const RegionLocator regions(result.smoothed_input);
  SurfaceSeeds surface =
      phase("surface seeds", [&] { return surface_seeds(refinement.index(), pairs.uncovered, regions); });
  result.seeds = std::move(surface.seeds);
  result.surface = std::move(surface.surface);
  result.surface_quality = phase("surface quality", [&] { return measure_surface_quality(input, result.surface); });
  if (options.stop_after == Stage::Surface) return result;
  // Interior seeds (2.5), then the cells, repaired where they need it.
  InteriorSeedOptions interior = interior_options(options);
  interior.sampling.on_material_seeds = memory_guard_while_sampling(result.seeds, options);
  std::vector<Seed> caps = seed_interior(result.seeds, refinement.index(), regions, sizing, bounding_box(input),
                                         interior, phase, result.interior);
  // What the surface stages and the sampler freed goes back to the system before the largest
  // stage, and before the guard measures what the run holds.
  release_free_memory();
  guard_memory(result.seeds, options, result.interior);
  result.cells =
      conforming_cells(result.seeds, caps, refinement.index(), regions, cells_options(options), phase, result.interior);
  count_seed_kinds(result.seeds, result.interior);
  result.cells.region_names = result.surface.region_names;
  result.cell_quality =
      phase("cell quality", [&] { return measure_cell_quality(result.cells, {.threads = options.threads}); });
  return result;
}

// The clipped methods cut cells along the surfaces between regions; a face with one region on
// both sides (a sheet inside a material) would be lost.
void refuse_sheets(const SurfaceMesh& input) {
  for (std::size_t f = 0; f < input.num_faces(); ++f) {
    if (input.face_regions[f].back == input.face_regions[f].front) {
      throw Error(Error::Kind::InvalidGeometry,
                  "`method` 'clipped' cuts cells along closed surfaces only, and " + describe_face(input, f) +
                      " has the same region on both sides (an open sheet): mesh it with 'vorocrust'",
                  {.face = f, .option = "method"});
    }
  }
}

// The input face nearest `p` and its distance.
std::pair<std::uint32_t, double> nearest_face(const SurfaceMesh& mesh, const Point& p) {
  const auto [face, squared] = geometry::nearest_face(geometry::face_tree(mesh), mesh, p);
  return {face, std::sqrt(squared)};
}

double bounding_diagonal(const SurfaceMesh& mesh);

// The material seeds of a given seeds file, each checked to lie in the region it names: a seed
// outside its region would leave part of the region to no cell.
std::vector<Seed> given_seeds(const std::filesystem::path& path, const SurfaceMesh& input) {
  const std::vector<Seed> all = read_seeds_csv(path);
  const RegionLocator locate(input);
  std::vector<Seed> seeds;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Seed& s = all[i];
    if (s.region <= 0) continue;
    const std::int32_t region = locate.region_of(s.position);
    if (region != s.region) {
      const auto [face, distance] = nearest_face(input, s.position);
      if (distance <= 1e-12 * bounding_diagonal(input)) {
        throw Error(Error::Kind::InvalidGeometry,
                    c_format("%s: seed %zu (%s) lies on the surface (%s), where no cell can tell its side: move it "
                             "into region %d",
                             path.string().c_str(), i + 1, describe_point(s.position).c_str(),
                             describe_face(input, face).c_str(), s.region),
                    {.option = "seeds"});
      }
      throw Error(Error::Kind::InvalidGeometry,
                  c_format("%s: seed %zu (%s) is labelled region %d but lies in region %d", path.string().c_str(),
                           i + 1, describe_point(s.position).c_str(), s.region, region),
                  {.option = "seeds"});
    }
    seeds.push_back(s);
  }
  if (seeds.empty()) {
    throw Error(Error::Kind::InvalidGeometry, path.string() + ": no seed is labelled with a material (label above 0)",
                {.option = "seeds"});
  }
  return seeds;
}

double bounding_diagonal(const SurfaceMesh& mesh) {
  const geometry::Box box = bounding_box(mesh);
  return (box.hi - box.lo).norm();
}

// The clipped methods (Ebeida and Mitchell; Yan et al.): seeds inside each material only, each
// material's Voronoi cells cut to its region.
MeshResult run_clipped(const SurfaceMesh& model, const MeshOptions& options, const ProgressCallback& progress) {
  MeshResult result;
  Phases phase(result.timings, progress);
  SurfaceMesh input = labelled_domain(model, options, phase, result);
  refuse_sheets(input);
  clipping::ClippedOptions clipped;
  clipped.radius = std::isfinite(options.max_size) ? options.max_size : bounding_diagonal(input) / 20;
  clipped.mode = options.interior;
  clipped.cvt_iterations = options.cvt_iterations;
  clipped.sliver_angle = options.sliver_angle;
  clipped.sharp_angle_degrees = options.sharp_angle();
  clipped.seed = options.seed;
  clipped.threads = options.threads;
  if (!options.seeds_file.empty()) clipped.given = phase("reading seeds", [&] { return given_seeds(options.seeds_file, input); });
  clipped.before_cells = [&](const std::vector<Seed>& seeds) { guard_memory(seeds, options, result.interior); };
  clipping::ClippedMesh mesh = clipping::clipped_cells(input, clipped, phase);
  result.seeds = std::move(mesh.seeds);
  result.cells = std::move(mesh.cells);
  result.clipping = mesh.stats;
  result.dual_tets = phase("dual tetrahedra", [&] { return clipping::measure_dual_tets(result.cells); });
  if (options.weld > 0) {
    result.welding = phase("welding", [&] {
      return cells::weld_short_edges(result.cells, std::vector<double>(result.cells.cells.size(), clipped.radius),
                                     options.weld);
    });
  }
  count_seed_kinds(result.seeds, result.interior);
  result.cells.region_names = RegionLocator(input).region_names();
  // The boundary is the input's own: the surface figures compare it with itself.
  result.smoothed_input = input;
  result.surface = std::move(input);
  result.surface_quality =
      phase("surface quality", [&] { return measure_surface_quality(result.smoothed_input, result.surface); });
  result.cell_quality =
      phase("cell quality", [&] { return measure_cell_quality(result.cells, {.threads = options.threads}); });
  return result;
}

}  // namespace

SurfaceMesh prepare_domain(const SurfaceMesh& model, const MeshOptions& options, SelfIntersectionStats* stats) {
  SurfaceMesh input = model;
  if (options.box) {
    const auto& b = *options.box;
    input = enclose_in_box(model, geometry::Box{Point(b[0], b[1], b[2]), Point(b[3], b[4], b[5])});
  } else if (needs_box(model) && !holds_its_box(model)) {
    input = enclose_in_box(model, default_box(model));
  }
  if (options.self_intersections == SelfIntersections::Resolve) input = resolve_self_intersections(input, stats);
  return input;
}

MeshResult generate_mesh(const SurfaceMesh& model, const MeshOptions& options, const ProgressCallback& progress) {
  options.check();
  // Every parallel stage runs in this arena: a program that asks for n threads gets at most n,
  // with or without a ThreadLimit of its own.
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  return arena.execute([&] {
    return options.method == Method::Clipped ? run_clipped(model, options, progress)
                                             : run_pipeline(model, options, progress);
  });
}

}  // namespace vorocrust
