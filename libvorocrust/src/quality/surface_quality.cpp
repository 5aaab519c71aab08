// The surface-quality figures of the paper's section 3: angles and triangle quality of the output,
// Hausdorff distance and topology against the input.
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <limits>
#include <optional>
#include <string>

#include "core/surface_measures.hpp"
#include "geometry/box_tree.hpp"
#include "quality/hausdorff.hpp"
#include "quality/surface_topology.hpp"
#include "geometry/triangle_shape.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/quality.hpp"
#include "vorocrust/regions.hpp"

namespace vorocrust {

void QualityOptions::check() const {
  if (random_samples > 100'000'000) {
    throw Error(Error::Kind::Usage, "--samples must be at most 100000000, got " + std::to_string(random_samples));
  }
  if (histogram_bins < 1 || histogram_bins > 1000) {
    throw Error(Error::Kind::Usage,
                "the quality histogram needs 1 to 1000 bins, got " + std::to_string(histogram_bins));
  }
}

namespace {

void measure_shapes(const SurfaceMesh& output, std::size_t bins, SurfaceQuality& q) {
  q.triangles = output.num_faces();
  q.quality_histogram.assign(bins, 0);
  q.min_angle_degrees = q.min_quality = std::numeric_limits<double>::infinity();
  q.max_angle_degrees = -std::numeric_limits<double>::infinity();
  std::size_t below_30 = 0, above_90 = 0;
  double quality_sum = 0;
  for (const Triangle& t : output.triangles) {
    const geometry::TriangleShape shape = geometry::triangle_shape(output.vertices[t[0]], output.vertices[t[1]], output.vertices[t[2]]);
    for (int k = 0; k < 3; ++k) {
      q.min_angle_degrees = std::min(q.min_angle_degrees, shape.angles_degrees[k]);
      q.max_angle_degrees = std::max(q.max_angle_degrees, shape.angles_degrees[k]);
      below_30 += shape.angles_degrees[k] < 30;
      above_90 += shape.obtuse[k];
    }
    q.min_quality = std::min(q.min_quality, shape.quality);
    quality_sum += shape.quality;
    ++q.quality_histogram[std::min(bins - 1, static_cast<std::size_t>(shape.quality * static_cast<double>(bins)))];
  }
  const double angles = 3.0 * static_cast<double>(q.triangles);
  q.percent_angles_below_30 = 100.0 * static_cast<double>(below_30) / angles;
  q.percent_angles_above_90 = 100.0 * static_cast<double>(above_90) / angles;
  q.mean_quality = quality_sum / static_cast<double>(q.triangles);
}

// What the distance and topology need of one surface.
struct Side {
  SurfaceTopology topology;
  std::vector<Point> samples;
  std::optional<geometry::BoxTree> faces;
};

Side prepare(const SurfaceMesh& mesh, std::size_t random_samples, std::uint64_t seed) {
  const EdgeTopology edges = build_edge_topology(mesh);
  return {surface_topology(mesh, edges), quality::surface_samples(mesh, edges, random_samples, seed), geometry::face_tree(mesh)};
}

// The regions of space the surface cuts out but the outside, in label order; nullopt where labels
// are at odds on one region of space.
std::optional<std::vector<RegionSummary>> regions_inside(const SurfaceMesh& mesh) {
  try {
    std::vector<RegionSummary> regions = find_regions(mesh);
    if (!regions.empty()) regions.erase(regions.begin());
    return regions;
  } catch (const Error& e) {
    if (e.kind() != Error::Kind::InvalidGeometry) throw;
    return std::nullopt;
  }
}

std::optional<double> volume_of(const std::optional<std::vector<RegionSummary>>& regions) {
  if (!regions) return std::nullopt;
  double volume = 0;
  for (const RegionSummary& r : *regions) volume += r.volume;
  return volume;
}

// The regions of both surfaces matched by name.
std::vector<RegionVolume> matched_by_name(const std::optional<std::vector<RegionSummary>>& input,
                                          const std::optional<std::vector<RegionSummary>>& output) {
  std::vector<RegionVolume> out;
  const auto entry = [&](const std::string& name) -> RegionVolume& {
    const auto it = std::find_if(out.begin(), out.end(), [&](const RegionVolume& v) { return v.name == name; });
    return it != out.end() ? *it : out.emplace_back(RegionVolume{name, std::nullopt, std::nullopt});
  };
  if (input) {
    for (const RegionSummary& r : *input) entry(r.name).input = r.volume;
  }
  if (output) {
    for (const RegionSummary& r : *output) entry(r.name).output = r.volume;
  }
  return out;
}

}  // namespace

std::vector<double> triangle_qualities(const SurfaceMesh& mesh) {
  std::vector<double> quality;
  quality.reserve(mesh.num_faces());
  for (const Triangle& t : mesh.triangles) {
    quality.push_back(geometry::triangle_shape(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]).quality);
  }
  return quality;
}

SurfaceQuality measure_surface_quality(const SurfaceMesh& input, const SurfaceMesh& output,
                                       const QualityOptions& options) {
  options.check();
  if (input.num_faces() == 0) throw Error(Error::Kind::InvalidGeometry, "the input surface has no triangles");
  if (output.num_faces() == 0) throw Error(Error::Kind::InvalidGeometry, "the output surface has no triangles");
  SurfaceQuality q;
  q.bounding_box_diagonal = bounding_box_diagonal(input);
  if (!(q.bounding_box_diagonal > 0)) {
    throw Error(Error::Kind::InvalidGeometry,
                "the input surface has no extent (every vertex at one point): no distance can be relative to it");
  }

  // The two surfaces are prepared side by side, each serially, so neither depends on the thread
  // count. Their seeds differ so that equal surfaces are not sampled at equal points.
  Side in, out;
  std::optional<std::vector<RegionSummary>> input_regions, output_regions;
  tbb::parallel_invoke([&] { in = prepare(input, options.random_samples, options.seed); },
                       [&] { out = prepare(output, options.random_samples, options.seed + 1); },
                       [&] { measure_shapes(output, options.histogram_bins, q); },
                       [&] { input_regions = regions_inside(input); },
                       [&] { output_regions = regions_inside(output); });
  q.input_volume = volume_of(input_regions);
  q.output_volume = volume_of(output_regions);
  q.region_volumes = matched_by_name(input_regions, output_regions);
  q.input_topology = std::move(in.topology);
  q.output_topology = std::move(out.topology);
  q.topology_matches = same_topology(q.input_topology, q.output_topology);
  q.input_samples = in.samples.size();
  q.output_samples = out.samples.size();
  const double negligible = kNegligibleRelativeDistance * q.bounding_box_diagonal;
  q.input_to_output = quality::farthest_sample_distance(in.samples, output, *out.faces, negligible);
  q.output_to_input = quality::farthest_sample_distance(out.samples, input, *in.faces, negligible);
  q.hausdorff = std::max(q.input_to_output, q.output_to_input);
  q.hausdorff_relative = q.hausdorff / q.bounding_box_diagonal;
  return q;
}

}  // namespace vorocrust
