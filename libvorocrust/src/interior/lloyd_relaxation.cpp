// Lloyd iterations over the interior seeds (paper 2.5).
#include "interior/lloyd_relaxation.hpp"

#include <algorithm>

#include "geometry/ball_tree.hpp"
#include "refinement/ball_index.hpp"
#include "vorocrust/cells.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust {

double lloyd_relaxation(std::vector<Seed>& seeds, const BallIndex& protecting_balls, int iterations, int threads,
                        const ProgressCallback& progress) {
  BallTree surface_balls;
  for (std::uint32_t i = 0; i < seeds.size(); ++i) {
    if (seeds[i].kind == SeedKind::Surface) surface_balls.insert(seeds[i].position, seeds[i].radius, i);
  }
  CellsOptions options;
  options.threads = threads;
  double largest_move = 0;
  for (int iteration = 0; iteration < iterations; ++iteration) {
    if (progress && !progress({"cvt", static_cast<double>(iteration) / iterations})) {
      throw Error(Error::Kind::Cancelled, "cancelled");
    }
    const VoronoiMesh mesh = compute_cells(seeds, options);
    largest_move = 0;
    for (const VoronoiCell& cell : mesh.cells) {
      Seed& seed = seeds[cell.seed];
      if (seed.kind != SeedKind::Interior) continue;
      Point step = cell.centroid - seed.position;
      for (int halving = 0; halving < 4; ++halving, step *= 0.5) {
        const Point moved = seed.position + step;
        if (protecting_balls.covers(moved) || surface_balls.contains(moved)) continue;
        largest_move = std::max(largest_move, step.norm() / seed.radius);
        seed.position = moved;
        break;
      }
    }
  }
  return largest_move;
}

}  // namespace vorocrust
