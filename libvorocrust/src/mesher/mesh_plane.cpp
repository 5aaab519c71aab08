// The 2D pipeline (paper 2.6): read -> corners and chains -> circles -> seed pairs -> interior
// seeds -> cells, labelled by the regions they fill.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "cells/plane_cells.hpp"
#include "core/union_find.hpp"
#include "features/plane_chains.hpp"
#include "geometry/plane_tree.hpp"
#include "interior/sample_plane.hpp"
#include "refinement/protect_chains.hpp"
#include "seeds/circle_pairs.hpp"
#include "vorocrust/plane.hpp"
#include "vorocrust/threads.hpp"

namespace vorocrust {

namespace {

class Clock {
 public:
  explicit Clock(PlaneStats& stats) : stats_(stats) {}
  template <class F>
  auto operator()(const char* phase, F&& work) {
    const auto begin = std::chrono::steady_clock::now();
    struct Record {
      PlaneStats& stats;
      const char* phase;
      std::chrono::steady_clock::time_point begin;
      ~Record() {
        stats.seconds.emplace_back(phase, std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count());
      }
    } record{stats_, phase, begin};
    return work();
  }

 private:
  PlaneStats& stats_;
};

std::vector<Point2> positions_of(const std::vector<Seed>& seeds) {
  std::vector<Point2> out;
  out.reserve(seeds.size());
  for (const Seed& s : seeds) out.emplace_back(s.position.x(), s.position.y());
  return out;
}

// Lloyd iterations on the interior seeds: each moves to its cell's centroid where that lies
// clear of the circles; the boundary seeds stay.
void relax(std::vector<Seed>& seeds, std::size_t first_interior, const Eigen::AlignedBox2d& frame,
           const interior::PlaneSpacing& spacing, int iterations) {
  for (int it = 0; it < iterations; ++it) {
    const std::vector<cells::PlanePolygon> polygons = cells::plane_voronoi_cells(positions_of(seeds), frame);
    for (std::size_t i = first_interior; i < seeds.size(); ++i) {
      Point2 centroid;
      cells::polygon_area(polygons[i].vertices, &centroid);
      if (frame.contains(centroid) && !spacing.in_clearance(centroid)) {
        seeds[i].position = Point(centroid.x(), centroid.y(), 0);
      }
    }
  }
}

// Regions: seeds joined by an edge that no pair's chord makes belong to one; a region reaching
// the frame, or holding a hole point, is not meshed; region points label the others.
std::vector<std::int32_t> label_regions(const PlanarDomain& d, const std::vector<Seed>& seeds,
                                        const std::vector<std::uint32_t>& twin, const cells::PlaneAssembly& assembly,
                                        const features::PlaneFeatures& features,
                                        std::vector<std::string>& names) {
  const std::size_t n = seeds.size();
  UnionFind same(n);
  std::vector<bool> on_frame(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::int64_t j : assembly.across[i]) {
      if (j < 0) on_frame[i] = true;
      else if (i >= twin.size() || twin[i] != static_cast<std::uint32_t>(j)) same.unite(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j));
    }
  }
  constexpr std::int32_t kUnset = -1, kHole = -2;
  std::vector<std::int32_t> root_label(n, kUnset);
  for (std::size_t i = 0; i < n; ++i) {
    if (on_frame[i]) root_label[same.find(static_cast<std::uint32_t>(i))] = kOutsideRegion;
  }
  const std::vector<Point2> positions = positions_of(seeds);
  const geometry::PlaneTree tree(positions);
  const auto root_at = [&](const Point2& p) {
    std::uint32_t nearest;
    double squared;
    tree.nearest(p, 1, &nearest, &squared);
    return same.find(nearest);
  };
  for (const Point2& h : d.holes) {
    const std::uint32_t r = root_at(h);
    if (root_label[r] != kOutsideRegion) root_label[r] = kHole;
  }
  std::int32_t highest = 0;
  std::map<std::uint32_t, std::size_t> labelled_by;
  for (std::size_t k = 0; k < d.regions.size(); ++k) {
    const RegionPoint& p = d.regions[k];
    const std::uint32_t r = root_at(p.at);
    const std::string which = "region point " + std::to_string(k + 1) + " at " + describe_point(p.at);
    if (root_label[r] == kOutsideRegion) {
      throw Error(Error::Kind::InvalidGeometry, which + " lies in no closed region: outside the domain, or its region's boundary is open",
                  {.file = d.file, .line = p.line});
    }
    if (root_label[r] == kHole) {
      throw Error(Error::Kind::InvalidGeometry, which + " lies in a hole", {.file = d.file, .line = p.line});
    }
    if (root_label[r] != kUnset && root_label[r] != p.label) {
      throw Error(Error::Kind::InvalidGeometry, which + " gives label " + std::to_string(p.label) + " to the region that region point " +
                                                    std::to_string(labelled_by[r] + 1) + " labels " + std::to_string(root_label[r]),
                  {.file = d.file, .line = p.line});
    }
    root_label[r] = p.label;
    labelled_by[r] = k;
    highest = std::max(highest, p.label);
  }
  // Regions without a point are labelled after the highest label, in seed order.
  std::vector<std::uint32_t> unlabelled;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t r = same.find(static_cast<std::uint32_t>(i));
    if (root_label[r] == kUnset) {
      root_label[r] = ++highest;
      unlabelled.push_back(r);
    }
  }
  names.assign(static_cast<std::size_t>(highest) + 1, "");
  names[0] = "outside";
  for (std::size_t k = 0; k < d.region_names.size() && k < names.size(); ++k) {
    if (!d.region_names[k].empty()) names[k] = d.region_names[k];
  }
  for (std::size_t l = 1; l < names.size(); ++l) {
    if (names[l].empty()) names[l] = "region" + std::to_string(l);
  }
  if (d.regions.empty() && unlabelled.size() == 1) names[1] = "inside";
  std::vector<std::int32_t> label(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t l = root_label[same.find(static_cast<std::uint32_t>(i))];
    label[i] = l == kHole ? kOutsideRegion : l;
  }
  // A free end of a segment must lie inside a region: outside one, the boundary has a gap there.
  for (Index v = 0; v < d.points.size(); ++v) {
    if (!features.corner[v] || features.leaving[v].size() != 1) continue;
    if (label[root_at(d.points[v])] == kOutsideRegion) {
      std::size_t line = 0;
      for (std::size_t s = 0; s < d.segments.size(); ++s) {
        if ((d.segments[s][0] == v || d.segments[s][1] == v) && s < d.segment_lines.size()) line = d.segment_lines[s];
      }
      throw Error(Error::Kind::InvalidGeometry, "a segment ends at " + describe_point(d.points[v]) +
                                                    " outside every closed region: the boundary has a gap there, or the segment is stray",
                  {.file = d.file, .line = line});
    }
  }
  if (std::none_of(label.begin(), label.end(), [](std::int32_t l) { return l > 0; })) {
    throw Error(Error::Kind::InvalidGeometry, "the segments enclose no region to mesh: is the boundary open?", {.file = d.file});
  }
  return label;
}

}  // namespace

PlaneMesh mesh_plane(const PlanarDomain& input, const PlaneOptions& options) {
  options.check();
  const ThreadLimit threads(options.threads);
  PlaneMesh mesh;
  Clock clock(mesh.stats);
  const PlanarDomain d = clock("input", [&] { return prepare_planar_domain(input); });
  const features::PlaneFeatures features = clock("features", [&] { return features::find_plane_features(d, options.sharp_angle_degrees); });
  const SizingField sizing = options.sizing_file.empty() ? SizingField(options.max_size)
                                                         : SizingField(options.max_size, options.sizing_file, true);
  const refinement::PlaneProtection protection =
      clock("refinement", [&] { return refinement::protect_chains(d, features, sizing, options.lipschitz); });
  seeds::PlaneBoundarySeeds boundary = clock("seeds", [&] { return seeds::circle_pairs(protection); });

  Eigen::AlignedBox2d frame;
  double widest = 0;
  for (const PlaneCircle& c : protection.circles) {
    frame.extend(c.centre);
    widest = std::max(widest, c.radius);
  }
  for (const auto& s : d.segments) {
    frame.extend(d.points[s[0]]);
    frame.extend(d.points[s[1]]);
  }
  const double diagonal = frame.diagonal().norm();
  const double margin = std::max(0.05 * diagonal, 2 * widest);
  frame = Eigen::AlignedBox2d(frame.min() - Point2::Constant(margin), frame.max() + Point2::Constant(margin));

  const interior::PlaneSpacing spacing(protection.circles, sizing, options.lipschitz, frame.diagonal().norm() / 8, frame);
  // The lattice's spacing: the boundary's coarsest (the widest circle), at most max_size; where
  // the spacing is smaller, darts fill in.
  const double lattice = std::min(options.max_size, widest);
  std::vector<Seed> seeds = boundary.seeds;
  const std::size_t first_interior = seeds.size();
  clock("interior", [&] {
    const std::vector<Seed> inner = interior::sample_plane(boundary.seeds, spacing, frame, options.interior, lattice, options.seed);
    seeds.insert(seeds.end(), inner.begin(), inner.end());
    if (options.interior == InteriorMode::Cvt) relax(seeds, first_interior, frame, spacing, options.cvt_iterations);
    return 0;
  });

  const std::vector<Point2> positions = positions_of(seeds);
  const cells::PlaneAssembly assembly = clock("cells", [&] {
    const std::vector<cells::PlanePolygon> polygons = cells::plane_voronoi_cells(positions, frame);
    return cells::weld_plane_cells(polygons, positions, protection.circles, boundary.on_circles, 1e-10 * frame.diagonal().norm());
  });
  const std::vector<std::int32_t> label = clock("regions", [&] {
    return label_regions(d, seeds, boundary.twin, assembly, features, mesh.region_names);
  });

  // The meshed cells, their points renumbered in first use.
  std::vector<std::int32_t> cell_of(seeds.size(), kNoCell);
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    seeds[i].region = label[i];
    if (i >= first_interior && label[i] == kOutsideRegion) seeds[i].kind = SeedKind::Outside;
    if (label[i] > 0) cell_of[i] = static_cast<std::int32_t>(mesh.cells.size()), mesh.cells.push_back({});
  }
  std::vector<Index> point_of(assembly.points.size(), static_cast<Index>(-1));
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    if (cell_of[i] == kNoCell) continue;
    PlaneCell& cell = mesh.cells[static_cast<std::size_t>(cell_of[i])];
    cell.seed = static_cast<Index>(i);
    cell.region = label[i];
    std::vector<Point2> ring;
    for (std::size_t k = 0; k < assembly.polygons[i].size(); ++k) {
      const Index v = assembly.polygons[i][k];
      if (point_of[v] == static_cast<Index>(-1)) {
        point_of[v] = static_cast<Index>(mesh.points.size());
        mesh.points.push_back(assembly.points[v]);
      }
      cell.points.push_back(point_of[v]);
      ring.push_back(assembly.points[v]);
      const std::int64_t j = assembly.across[i][k];
      cell.across.push_back(j < 0 ? kNoCell : cell_of[static_cast<std::size_t>(j)]);
      cell.regions_across.push_back(j < 0 ? kOutsideRegion : label[static_cast<std::size_t>(j)]);
      cell.seeds_across.push_back(j);
    }
    cell.area = cells::polygon_area(ring, &cell.centroid);
  }
  mesh.seeds = std::move(seeds);
  mesh.circles = protection.circles;
  mesh.domain = d;
  PlaneStats& stats = mesh.stats;
  stats.corners = static_cast<std::size_t>(std::count(features.corner.begin(), features.corner.end(), true));
  stats.chains = features.chains.size();
  stats.circles = protection.circles.size();
  stats.refinement_rounds = protection.rounds;
  for (const Seed& s : mesh.seeds) {
    if (s.kind == SeedKind::Surface) ++stats.pair_seeds;
    else if (s.kind == SeedKind::Cap) ++stats.cap_seeds;
    else if (s.kind == SeedKind::Interior) ++stats.interior_seeds;
    else ++stats.outside_seeds;
  }
  return mesh;
}

std::vector<std::string_view> plane_option_names() {
  return {"lipschitz", "max_size", "sizing", "sharp_angle", "interior", "cvt_iterations", "seed", "threads"};
}

PlaneOptions plane_options(const MeshOptions& options) {
  PlaneOptions p;
  p.lipschitz = options.lipschitz;
  p.max_size = options.max_size;
  p.sizing_file = options.sizing_file;
  p.sharp_angle_degrees = options.sharp_angle();
  p.interior = options.interior;
  p.cvt_iterations = options.cvt_iterations;
  p.seed = options.seed;
  p.threads = options.threads;
  return p;
}

void PlaneOptions::check() const {
  const auto bad = [](const char* option, const std::string& why) {
    throw Error(Error::Kind::Usage, std::string(option) + " " + why, {.option = option});
  };
  if (!(lipschitz > 0 && lipschitz < 1)) bad("lipschitz", "must lie in (0, 1)");
  if (!(max_size > 0)) bad("max_size", "must be positive");
  if (!(sharp_angle_degrees > 0 && sharp_angle_degrees < 180)) bad("sharp_angle", "must lie in (0, 180) degrees");
  if (cvt_iterations < 0) bad("cvt_iterations", "must not be negative");
}

}  // namespace vorocrust
