#include "quality/hausdorff.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <random>

#include "geometry/nearest_face.hpp"
#include "geometry/curve_order.hpp"
#include "geometry/surface_sampling.hpp"

namespace vorocrust::quality {

namespace {

// Orders points along a Morton curve: neighbours in the list are mostly neighbours in space, so
// consecutive nearest-face searches walk the same tree nodes and faces while they are cached.
void sort_along_curve(std::vector<Point>& points) {
  const std::vector<std::uint32_t> order =
      geometry::curve_order(points.size(), [&](std::size_t i) -> const Point& { return points[i]; });
  std::vector<Point> sorted(points.size());
  for (std::size_t i = 0; i < order.size(); ++i) sorted[i] = points[order[i]];
  points = std::move(sorted);
}

}  // namespace

std::vector<Point> surface_samples(const SurfaceMesh& mesh, const EdgeTopology& topology, std::size_t random_points,
                                   std::uint64_t seed) {
  std::vector<Point> samples;
  samples.reserve(mesh.num_vertices() + topology.num_edges() + random_points);
  // Vertices no face uses are not on the surface.
  std::vector<char> used(mesh.num_vertices(), 0);
  for (const Triangle& t : mesh.triangles)
    for (Index v : t) used[v] = 1;
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v)
    if (used[v]) samples.push_back(mesh.vertices[v]);
  for (const auto& [a, b] : topology.edges) samples.push_back(0.5 * (mesh.vertices[a] + mesh.vertices[b]));

  std::vector<double> twice_areas(mesh.num_faces());  // only the proportions matter
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[f];
    twice_areas[f] = (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).norm();
  }
  const geometry::WeightedPick pick(twice_areas);
  if (!(pick.total() > 0)) random_points = 0;
  std::mt19937_64 rng(seed ^ 0x9a05d0f1ull);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (std::size_t k = 0; k < random_points; ++k) {
    const Triangle& t = mesh.triangles[pick(unit(rng))];
    const double u = unit(rng), v = unit(rng);
    samples.push_back(geometry::point_in_triangle(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], u, v));
  }
  sort_along_curve(samples);
  return samples;
}

double farthest_sample_distance(const std::vector<Point>& samples, const SurfaceMesh& to, const geometry::BoxTree& faces,
                                double negligible) {
  // Only the farthest sample matters, so a sample's search stops as soon as the other surface
  // comes within the farthest distance found so far, or within `negligible`: most searches end
  // at their first faces. The answer is still exact and independent of the thread count: a
  // sample cut short is no farther than a distance some other sample really has (or than
  // `negligible`, and so counts as 0), and the farthest one is never cut short below its own
  // distance.
  const double negligible_squared = negligible * negligible;
  std::atomic<double> farthest_squared{0.0};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples.size(), 256), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const Point& p = samples[i];
      double known = farthest_squared.load(std::memory_order_relaxed);
      const double squared =
          geometry::nearest_face(faces, to, p, geometry::EveryFace{}, std::max(known, negligible_squared)).second;
      if (squared <= negligible_squared) continue;
      while (squared > known && !farthest_squared.compare_exchange_weak(known, squared, std::memory_order_relaxed)) {
      }
    }
  });
  return std::sqrt(farthest_squared.load());
}

}  // namespace vorocrust::quality
