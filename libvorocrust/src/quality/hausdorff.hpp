// Internal: the one-sided distance from one surface to another, over dense samples of the first
// (the pieces of the Hausdorff distance in vorocrust/quality.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "core/edge_topology.hpp"
#include "geometry/box_tree.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::quality {

// Every vertex a face uses, every edge midpoint, and `random_points` points uniform over the
// surface's area, drawn from `seed`, all ordered along a space-filling curve. Zero-area surfaces
// get no random points.
std::vector<Point> surface_samples(const SurfaceMesh& mesh, const EdgeTopology& topology, std::size_t random_points,
                                   std::uint64_t seed);

// The largest distance from a sample to the nearest face of `to` (whose face tree is `faces`),
// exact up to rounding, where distances up to `negligible` count as 0; 0 without samples. Runs in
// parallel; the result does not depend on the thread count.
double farthest_sample_distance(const std::vector<Point>& samples, const SurfaceMesh& to, const geometry::BoxTree& faces,
                                double negligible);

}  // namespace vorocrust::quality
