#include "clipping/clipped_cells.hpp"

#include <cmath>

#include "clipping/poisson_disk_seeds.hpp"
#include "core/split_mix.hpp"
#include "seeds/locate_regions.hpp"
#include "vorocrust/cells.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust::clipping {
namespace {

// A cubic lattice's Voronoi vertices are each shared by eight cells and its edges by four, and a
// CAD model's faces often lie on its bisectors: a clipping decided by the side of the surface
// each point lies on cannot settle such ties. Each point moves by up to a thousandth of the
// spacing, in a direction drawn from the run's random seed: no four seeds on a circle, no face
// on a bisector, and faces of at most that size where the lattice had an edge.
constexpr double kLatticeJitter = 1e-3;

std::vector<Seed> lattice_seeds(const SurfaceMesh& domain, std::int32_t material, double spacing, std::uint64_t seed) {
  Eigen::AlignedBox3d box;
  for (const Point& p : domain.vertices) box.extend(p);
  const RegionLocator locate(domain);
  std::vector<Seed> seeds;
  const Point extent = box.sizes();
  const Eigen::Vector3i n = (extent / spacing).array().floor().cast<int>();
  // Centred in the box, so that a lattice that fits the box exactly keeps off its sides.
  const Point lo = box.min() + (extent - spacing * n.cast<double>()) / 2;
  for (int z = 0; z <= n.z(); ++z) {
    for (int y = 0; y <= n.y(); ++y) {
      for (int x = 0; x <= n.x(); ++x) {
        SplitMix64 random =
            SplitMix64::stream(seed, static_cast<std::uint64_t>((z * (n.y() + 1) + y) * (n.x() + 1) + x));
        const Point jitter(random.unit() - 0.5, random.unit() - 0.5, random.unit() - 0.5);
        const Point p = lo + spacing * (Point(x, y, z) + 2 * kLatticeJitter * jitter);
        if (locate.region_of(p) == material) seeds.push_back({p, material, spacing, SeedKind::Interior});
      }
    }
  }
  return seeds;
}

// The Voronoi cells of the material seeds, bounded by outside seeds `margin` beyond the domain's
// box, cut to the material. Outside seeds nearer a point of the surface than every material seed
// would take part of it from the cells (a lattice that misses a thin part, seeds Lloyd moved):
// then the margin grows fourfold, up to the box's diagonal, beyond which no point of the box is
// nearer an outside seed than any seed inside it.
struct Clipping {
  std::vector<Seed> seeds;  // the material seeds, then the outside seeds
  VoronoiMesh cells;
  ClippingStats stats;
};

Clipping clip(const SurfaceMesh& domain, std::int32_t material, const std::vector<Seed>& seeds,
              const ClippedOptions& options, Phases* phases) {
  Eigen::AlignedBox3d box;
  for (const Point& p : domain.vertices) box.extend(p);
  const double diagonal = box.diagonal().norm();
  for (double margin = std::min(1.5 * options.radius, diagonal);; margin = std::min(4 * margin, diagonal)) {
    Clipping c;
    c.seeds = seeds;
    for (Seed& s : outside_seeds(domain, margin, options.radius)) c.seeds.push_back(s);
    const auto cut = [&] {
      const VoronoiMesh cells = compute_cells(c.seeds, {.materials = {material}, .threads = options.threads});
      c.cells = clip_cells(cells, domain, material, &c.stats);
    };
    if (phases) {
      (*phases)("cells", cut);
    } else {
      cut();
    }
    if (c.stats.uncovered_triangles == 0) return c;
    if (margin >= diagonal) {
      throw Error(Error::Kind::Internal, "outside seeds beyond the domain's diagonal take part of its surface");
    }
  }
}

}  // namespace

ClippedMesh clipped_cells(const SurfaceMesh& domain, std::int32_t material, const ClippedOptions& options,
                          Phases& phases) {
  std::vector<Seed> seeds = phases("interior seeds", [&] {
    const std::vector<Seed> lattice = options.mode == InteriorMode::Lattice
                                          ? lattice_seeds(domain, material, options.radius, options.seed)
                                          : std::vector<Seed>{};
    return poisson_disk_seeds(domain, material, options.radius, options.seed, lattice);
  });
  if (options.mode == InteriorMode::Cvt) {
    phases("cvt", [&] {
      const RegionLocator locate(domain);
      for (int iteration = 0; iteration < options.cvt_iterations; ++iteration) {
        const Clipping c = clip(domain, material, seeds, options, nullptr);
        for (const VoronoiCell& cell : c.cells.cells) {
          if (locate.region_of(cell.centroid) == material) seeds[cell.seed].position = cell.centroid;
        }
      }
    });
  }
  if (options.before_cells) options.before_cells(seeds);
  Clipping c = clip(domain, material, seeds, options, &phases);
  return {std::move(c.seeds), std::move(c.cells), c.stats};
}

}  // namespace vorocrust::clipping
