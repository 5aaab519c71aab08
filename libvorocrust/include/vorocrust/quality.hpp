// vorocrust/quality.hpp — how good an output surface is and how closely it follows the input,
// in the figures of the paper's section 3.
//
// Angles and triangle quality describe the output surface alone:
// - the three corner angles of every triangle, in degrees; "below 30" and "above 90" are both
//   strict, so a right angle is not above 90 (decided by the sign of the edges' dot product, not
//   by a rounded angle). A corner with a zero-length edge has angle 0.
// - triangle quality Q = 6 S / (sqrt(3) h p), with S the area, h the longest edge and p half the
//   perimeter: 1 for the equilateral triangle, falling to 0 as the triangle flattens; 0 for a
//   triangle of zero area.
// The Hausdorff distance and the topology compare the output with the input:
// - each surface is sampled (every vertex a face uses, every edge midpoint, and random points
//   spread by area from a fixed seed, so equal inputs and options give equal figures whatever
//   the thread count), and each sample's exact distance to the other surface's triangles is
//   taken; the one-sided distance is the largest of them, the Hausdorff distance the larger of
//   the two one-sided ones. Being a maximum over samples it can only underestimate the true one.
//   Distances up to kNegligibleRelativeDistance times the input's bounding-box diagonal count as
//   0: they are the rounding of points that lie on the other surface, not a gap, so a surface
//   measured against itself is at distance exactly 0.
// - the volume of each region of space a surface cuts out but the outside (regions.hpp: the
//   regions of nested shells, materials, not the cavities of the outside), matched by name, and
//   their sum, the volume the surface encloses: how much each region and the whole shrank or
//   swelled against the input. A sheet inside a box changes only the regions it divides, not
//   the sum.
// - components are faces joined through shared edges, each with its Euler characteristic
//   V - E + F (2 for a sphere, 0 for a torus, 1 for a disc) and whether it is closed (no edge
//   with a single face).
// Nothing here yields NaN: degenerate triangles are measured like any other.
#pragma once

#include "vorocrust/api.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

inline constexpr double kNegligibleRelativeDistance = 1e-9;

struct VOROCRUST_API SurfaceTopology {
  std::size_t components = 0;
  // Per component, components in order of their smallest face index.
  std::vector<long> euler_characteristic;
  std::vector<bool> closed;
  std::size_t boundary_edges = 0;      // edges with one face
  std::size_t non_manifold_edges = 0;  // edges with three or more faces
};

VOROCRUST_API SurfaceTopology surface_topology(const SurfaceMesh& mesh);

// Same number of components and the same multiset of (Euler characteristic, closed) pairs.
VOROCRUST_API bool same_topology(const SurfaceTopology& a, const SurfaceTopology& b);

struct VOROCRUST_API QualityOptions {
  // Random points per surface, on top of its vertices and edge midpoints. With the default a
  // surface of 100 000 triangles is measured against itself in about half a second of one core
  // (bench/RESULTS.md).
  std::size_t random_samples = 100000;
  std::uint64_t seed = 0;
  std::size_t histogram_bins = 20;  // of triangle quality, evenly over [0, 1]

  // Throws Error(Usage) naming the first option out of its range.
  void check() const;
};

// 100 (after - before) / before, when both are known and `before` is not 0.
inline std::optional<double> percent_change(const std::optional<double>& before, const std::optional<double>& after) {
  if (!before || !after || *before == 0) return std::nullopt;
  return 100 * (*after - *before) / *before;
}

struct VOROCRUST_API RegionVolume {
  std::string name;
  std::optional<double> input, output;  // unset where that surface has no region of this name
  std::optional<double> change_percent() const { return percent_change(input, output); }
};

struct VOROCRUST_API SurfaceQuality {
  std::size_t triangles = 0;  // of the output
  double min_angle_degrees = 0, max_angle_degrees = 0;
  double percent_angles_below_30 = 0, percent_angles_above_90 = 0;  // of all 3 x triangles angles
  double min_quality = 0, mean_quality = 0;
  // Triangles per bin: bin k holds quality in [k/n, (k+1)/n), the last one also Q = 1.
  std::vector<std::size_t> quality_histogram;

  double hausdorff = 0;           // two-sided, in the input's units
  double hausdorff_relative = 0;  // divided by the input's bounding-box diagonal
  double input_to_output = 0;     // farthest input sample from the output surface
  double output_to_input = 0;     // farthest output sample from the input surface
  double bounding_box_diagonal = 0;  // of the input
  std::size_t input_samples = 0, output_samples = 0;

  // Unset for a surface whose regions cannot be told (labels at odds on one region of space).
  std::optional<double> input_volume, output_volume;
  // Per region but the outside, the input's in label order, then those of the output alone.
  std::vector<RegionVolume> region_volumes;
  // 100 (output - input) / input of the enclosed volume, when both are known and the input's is
  // not 0.
  std::optional<double> volume_change_percent() const { return percent_change(input_volume, output_volume); }

  SurfaceTopology input_topology, output_topology;
  bool topology_matches = false;  // same_topology(input_topology, output_topology)
};

// The triangle quality Q of every face of `mesh`, in face order, as defined above: what the
// front ends show per face (MeshLab's per-face quality), the figures measure_surface_quality
// summarises.
VOROCRUST_API std::vector<double> triangle_qualities(const SurfaceMesh& mesh);

// Throws Error(InvalidGeometry) when either surface has no triangle or the input has no extent
// (every vertex at one point), Error(Usage) for options out of range.
VOROCRUST_API SurfaceQuality measure_surface_quality(const SurfaceMesh& input, const SurfaceMesh& output,
                                       const QualityOptions& options = {});

}  // namespace vorocrust
