// Lloyd iterations over the interior seeds (paper 2.5).
#include "interior/lloyd_relaxation.hpp"

#include "interior/sample_interior.hpp"

#include <algorithm>
#include <limits>

#include "geometry/ball_tree.hpp"
#include "refinement/ball_index.hpp"
#include "vorocrust/cells.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust {

double lloyd_relaxation(std::vector<Seed>& seeds, const BallIndex& protecting_balls, int iterations, int threads,
                        const ProgressCallback& progress) {
  geometry::BallTree surface_balls;
  for (std::uint32_t i = 0; i < seeds.size(); ++i) {
    if (seeds[i].kind == SeedKind::Surface || seeds[i].kind == SeedKind::Cap) {
      surface_balls.insert(seeds[i].position, seeds[i].radius, i);
    }
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
      // A seed next to a surface seed's cell bounds that thin cell from inside: drawn to its own
      // centroid it would back away from the surface and stretch the surface cells. It moves along
      // the surface only, keeping its depth.
      const Seed* nearest_surface = nullptr;
      double nearest = std::numeric_limits<double>::infinity();
      for (const Index f : cell.faces) {
        const VoronoiFace& face = mesh.faces[f];
        const Index across = face.owner_seed == cell.seed ? face.neighbour_seed : face.owner_seed;
        if (seeds[across].kind != SeedKind::Surface && seeds[across].kind != SeedKind::Cap) continue;
        const double d = (seeds[across].position - seed.position).squaredNorm();
        if (d < nearest) nearest = d, nearest_surface = &seeds[across];
      }
      if (nearest_surface) {
        const Point away = (seed.position - nearest_surface->position).normalized();
        step -= std::max(0.0, step.dot(away)) * away;
      }
      for (int halving = 0; halving < 4; ++halving, step *= 0.5) {
        const Point moved = seed.position + step;
        if (protecting_balls.covers(moved, 1 + kBallClearance) || surface_balls.contains(moved)) continue;
        largest_move = std::max(largest_move, step.norm() / seed.radius);
        seed.position = moved;
        break;
      }
    }
  }
  return largest_move;
}

}  // namespace vorocrust
