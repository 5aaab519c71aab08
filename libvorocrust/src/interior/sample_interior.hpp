// Internal: seeds away from the surface (paper 2.5, appendix A.5).
//
// The surface seeds carry radii (the mean of their three balls); an interior seed z takes the
// region of its nearest surface seed and a radius that extends the surface sizing inward,
// r_z = min(sz(z), min over seeds q of r_q + L |z - q|), so cells grow away from the surface at
// the rate L allows. A candidate is refused when it lies inside a protecting ball (the surface
// facets are Voronoi facets only while no seed enters the union of balls) or within
// kBallClearance of one's sphere (a seed just outside a ball cuts small, highly skew faces
// about its centre, cap_seeds.hpp), inside a surface seed's ball or inside an interior seed's
// ball. The cap seeds given (pole_seeds) are placed first, as interior seeds of their ball's
// radius.
//
// Random: dart throwing over the input's bounding box grown 3x about its centre until 100
// consecutive misses, then spoke darts from every seed until each has missed 100 times in a row:
// a spoke from z spans [r_z, 2 r_z] in a random direction, and a new seed lands uniformly on the
// part of it no ball covers. Then the radii are made L-Lipschitz over all seeds; when that shrank
// a ball the spokes run again from the seeds whose own ball shrank or whose spokes reach a shrunk
// ball as it was (the paper's Q refilled with every seed; the others would meet the balls they
// met), until no ball shrinks. Spokes run on all threads:
// groups of neighbouring seeds far enough apart that their spokes cannot meet take their turns
// side by side, each seed drawing from its own random stream, so the seeds are the same on any
// number of threads.
// Lattice: first the points of a cubic lattice over the material regions (spacing: the median
// surface-seed radius, at most --max-size), each with a ball that covers its lattice
// cube, then the random sampling fills what they leave: the layer near the surface and the
// outside.
//
// Seeds whose region is 0 are kept as outside seeds: they bound the boundary cells.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "geometry/box_tree.hpp"
#include "vorocrust/modes.hpp"
#include "vorocrust/progress.hpp"
#include "vorocrust/stats.hpp"
#include "vorocrust/seeds.hpp"

namespace vorocrust {

class BallIndex;
class SizingField;

// Random interior seeds keep out of (1 + kBallClearance) times every protecting ball.
inline constexpr double kBallClearance = 0.3;

struct InteriorOptions {
  InteriorMode mode = InteriorMode::Random;
  double lipschitz = 0.25;
  std::uint64_t seed = 0;
  int misses = 100;  // consecutive misses that end dart throwing, and a spoke seed
  // Called with the number of material seeds placed so far (the cells they will make) each time
  // it has grown by a quarter; it may throw to stop the sampling (the memory guard: a run of far
  // too many cells stops here, before its seeds fill the memory).
  std::function<void(std::size_t)> on_material_seeds;
};


// Interior and outside seeds for the given surface seeds (surface seeds are not repeated), after
// the cap seeds, which are returned first. `domain` is the input's bounding box. Fills the
// sampling counts of `stats`.
std::vector<Seed> sample_interior(const std::vector<Seed>& surface_seeds, const std::vector<Seed>& cap_seeds,
                                  const BallIndex& protecting_balls,
                                  const SizingField& sizing, const geometry::Box& domain,
                                  const InteriorOptions& options, const ProgressCallback& progress,
                                  InteriorStats& stats);

}  // namespace vorocrust
