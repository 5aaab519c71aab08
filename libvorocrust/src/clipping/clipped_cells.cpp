#include "clipping/clipped_cells.hpp"

#include <cmath>

#include "clipping/poisson_disk_seeds.hpp"
#include "core/split_mix.hpp"
#include "seeds/locate_regions.hpp"
#include "vorocrust/cells.hpp"

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

VoronoiMesh clip(const SurfaceMesh& domain, std::int32_t material, const std::vector<Seed>& seeds,
                 const std::vector<Seed>& outside, const ClippedOptions& options, ClipStats* stats) {
  std::vector<Seed> all = seeds;
  all.insert(all.end(), outside.begin(), outside.end());
  return clip_cells(compute_cells(all, {.materials = {material}, .threads = options.threads}), domain, material, stats);
}

}  // namespace

ClippedMesh clipped_cells(const SurfaceMesh& domain, std::int32_t material, const ClippedOptions& options,
                          Phases& phases) {
  std::vector<Seed> seeds;
  if (!options.given.empty()) {
    for (const Seed& s : options.given) {
      if (s.region == material) seeds.push_back(s);
    }
  } else {
    seeds = phases("interior seeds", [&] {
      return options.mode == InteriorMode::Lattice ? lattice_seeds(domain, material, options.radius, options.seed)
                                                   : poisson_disk_seeds(domain, material, options.radius, options.seed);
    });
  }
  const std::vector<Seed> outside = outside_seeds(domain, options.radius);
  if (options.given.empty() && options.mode == InteriorMode::Cvt) {
    phases("cvt", [&] {
      const RegionLocator locate(domain);
      for (int iteration = 0; iteration < options.cvt_iterations; ++iteration) {
        const VoronoiMesh cells = clip(domain, material, seeds, outside, options, nullptr);
        for (const VoronoiCell& c : cells.cells) {
          if (locate.region_of(c.centroid) == material) seeds[c.seed].position = c.centroid;
        }
      }
    });
  }
  if (options.before_cells) options.before_cells(seeds);
  ClippedMesh result;
  std::vector<Seed> all = seeds;
  all.insert(all.end(), outside.begin(), outside.end());
  const VoronoiMesh cells =
      phases("cells", [&] { return compute_cells(all, {.materials = {material}, .threads = options.threads}); });
  result.cells = phases("clipping", [&] { return clip_cells(cells, domain, material, &result.stats); });
  result.seeds = std::move(all);
  return result;
}

}  // namespace vorocrust::clipping
