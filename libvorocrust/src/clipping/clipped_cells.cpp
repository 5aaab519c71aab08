#include "clipping/clipped_cells.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>

#include "clipping/edge_seeds.hpp"
#include "clipping/poisson_disk_seeds.hpp"
#include "core/c_format.hpp"
#include "core/split_mix.hpp"
#include "geometry/box_tree.hpp"
#include "geometry/closest_point.hpp"
#include "geometry/point_cloud.hpp"
#include "seeds/locate_regions.hpp"
#include "vorocrust/cells.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust::clipping {
namespace {

// A cubic lattice's Voronoi vertices are each shared by eight cells and its edges by four, and a
// CAD model's faces often lie on its bisectors (and grids of given seeds have the same ties): a
// clipping decided by the side of the surface each point lies on cannot settle such ties, and
// Voro++'s diagram, whose points compute_cells welds within up to 1e-6 of a cell's size, has
// already settled them its own way. Each seed moves by up to a thousandth of its spacing, in a
// direction drawn from the run's random seed: no four seeds on a circle, no face on a bisector,
// and faces of at most that size where the seeds had a common edge.
constexpr double kJitter = 1e-3;

// Item `item`'s move, in [-1/2, 1/2]^3, drawn from the run's seed.
Point jitter(std::uint64_t seed, std::uint64_t item) {
  SplitMix64 random = SplitMix64::stream(seed, item);
  return {random.unit() - 0.5, random.unit() - 0.5, random.unit() - 0.5};
}

// Given seeds moved as the lattice's are, each by a thousandth of the distance to its nearest
// other seed: a grid of seeds given for a box-shaped part has every tie above.
std::vector<Seed> jittered(std::vector<Seed> seeds, std::uint64_t seed) {
  const std::vector<Seed> original = seeds;
  const SeedCloud cloud{&original};
  const StaticKdTree<SeedCloud> tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    std::array<std::uint32_t, 2> index{};
    std::array<double, 2> squared{};
    if (tree.knnSearch(original[i].position.data(), 2, index.data(), squared.data()) < 2) continue;
    seeds[i].position += 2 * kJitter * std::sqrt(squared[1]) * jitter(seed, i);
  }
  return seeds;
}

// The lattice's points inside the materials, each with its region.
std::vector<Seed> lattice_seeds(const SurfaceMesh& domain, double spacing, std::uint64_t seed) {
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
        const Point move = jitter(seed, static_cast<std::uint64_t>((z * (n.y() + 1) + y) * (n.x() + 1) + x));
        const Point p = lo + spacing * (Point(x, y, z) + 2 * kJitter * move);
        const std::int32_t region = locate.region_of(p);
        if (region > 0) seeds.push_back({p, region, spacing, SeedKind::Interior});
      }
    }
  }
  return seeds;
}

// The Voronoi cells of each material's seeds, bounded by outside seeds `margin` beyond the
// domain's box, cut to the materials. Outside seeds nearer a point of the surface than every material seed
// would take part of it from the cells (a lattice that misses a thin part, seeds Lloyd moved):
// then the margin grows fourfold, up to the box's diagonal, beyond which no point of the box is
// nearer an outside seed than any seed inside it.
struct Clipping {
  std::vector<Seed> seeds;  // the material seeds, then the outside seeds
  VoronoiMesh cells;
  ClippingStats stats;
};

Clipping clip(const SurfaceMesh& domain, const std::vector<Seed>& seeds, const ClippedOptions& options,
              Phases* phases) {
  Eigen::AlignedBox3d box;
  for (const Point& p : domain.vertices) box.extend(p);
  const double diagonal = box.diagonal().norm();
  for (double margin = std::min(1.5 * options.radius, diagonal);; margin = std::min(4 * margin, diagonal)) {
    Clipping c;
    c.seeds = seeds;
    for (Seed& s : outside_seeds(domain, margin, options.radius)) c.seeds.push_back(s);
    VoronoiMesh diagrams;
    const auto voronoi = [&] { diagrams = material_diagrams(c.seeds, seeds.size(), options.threads); };
    const auto cut = [&] { c.cells = clip_cells(diagrams, domain, &c.stats); };
    if (phases) {
      (*phases)("cells", voronoi);
      (*phases)("clipping", cut);
    } else {
      voronoi();
      cut();
    }
    if (c.stats.uncovered_triangles == 0) return c;
    if (margin >= diagonal) {
      throw Error(Error::Kind::Internal, "outside seeds beyond the domain's diagonal take part of its surface");
    }
  }
}

// The surface of each material, for the seeds Yan et al.'s second phase keeps on it: the point of
// a material's boundary nearest a point, moved into the material by `inset` along the normal of
// its face (seeds exactly on an input face would tie with it in the clipping, as edge seeds do).
class MaterialBoundary {
 public:
  explicit MaterialBoundary(const SurfaceMesh& domain) : domain_(domain), tree_(geometry::face_tree(domain)) {}

  Point onto(const Point& p, std::int32_t material, double inset) const {
    const auto [face, squared] = tree_.nearest(p, [&](std::uint32_t f) {
      const RegionPair& r = domain_.face_regions[f];
      if (r.back == r.front || (r.back != material && r.front != material)) return kInfinity;
      return (closest(p, f) - p).squaredNorm();
    });
    if (face == geometry::BoxTree::kNoItem) return p;
    const Triangle& t = domain_.triangles[face];
    Point inward = (domain_.vertices[t[1]] - domain_.vertices[t[0]])
                       .cross(domain_.vertices[t[2]] - domain_.vertices[t[0]])
                       .normalized();
    if (domain_.face_regions[face].back == material) inward = -inward;
    return closest(p, face) + inset * inward;
  }

 private:
  static constexpr double kInfinity = std::numeric_limits<double>::infinity();
  Point closest(const Point& p, std::uint32_t f) const {
    const Triangle& t = domain_.triangles[f];
    return geometry::closest_on_triangle(p, domain_.vertices[t[0]], domain_.vertices[t[1]], domain_.vertices[t[2]]);
  }
  const SurfaceMesh& domain_;
  geometry::BoxTree tree_;
};

// Whether a cell has a face on the surface: toward no cell, or toward another material's.
bool on_the_surface(const VoronoiMesh& mesh, const VoronoiCell& cell) {
  return std::any_of(cell.faces.begin(), cell.faces.end(), [&](Index f) {
    const VoronoiFace& face = mesh.faces[f];
    return face.neighbour == kNoCell || mesh.cells[static_cast<std::size_t>(face.neighbour)].region != cell.region;
  });
}

// Yan et al.'s CVT (their 5.2): Lloyd iterations on the clipped cells, every interior seed to its
// cell's centroid; after the first half, the seeds of the cells on the surface move onto it (a
// thousandth of the radius inside) and stay there, each at the point nearest its centroid. Seeds
// of other kinds (on reflex edges) stay where they are.
void lloyd_iterations(const SurfaceMesh& domain, std::vector<Seed>& seeds, const ClippedOptions& options) {
  const RegionLocator locate(domain);
  const MaterialBoundary boundary(domain);
  const int free_rounds = (options.cvt_iterations + 1) / 2;
  std::vector<char> held(seeds.size(), 0);
  for (int iteration = 0; iteration < options.cvt_iterations; ++iteration) {
    const Clipping c = clip(domain, seeds, options, nullptr);
    for (const VoronoiCell& cell : c.cells.cells) {
      Seed& s = seeds[cell.seed];
      if (s.kind != SeedKind::Interior && !held[cell.seed]) continue;
      if (iteration == free_rounds && on_the_surface(c.cells, cell)) {
        held[cell.seed] = 1;
        s.kind = SeedKind::Surface;
      }
      if (held[cell.seed]) {
        s.position = boundary.onto(cell.centroid, cell.region, kJitter * options.radius);
      } else if (locate.region_of(cell.centroid) == cell.region) {
        s.position = cell.centroid;
      }
    }
  }
}

}  // namespace

ClippedMesh clipped_cells(const SurfaceMesh& domain, const ClippedOptions& options, Phases& phases) {
  std::int32_t materials = 0;
  for (const RegionPair& r : domain.face_regions) materials = std::max({materials, r.back, r.front});
  std::vector<Seed> seeds = phases("interior seeds", [&] {
    if (!options.given.empty()) {
      std::vector<Seed> given = jittered(options.given, options.seed);
      std::stable_sort(given.begin(), given.end(), [](const Seed& a, const Seed& b) { return a.region < b.region; });
      return given;
    }
    const std::vector<Seed> lattice = options.mode == InteriorMode::Lattice
                                          ? lattice_seeds(domain, options.radius, options.seed)
                                          : std::vector<Seed>{};
    std::vector<Seed> all;
    for (std::int32_t material = 1; material <= materials; ++material) {
      // The first material draws from the run's seed itself, the others from streams of it.
      const std::uint64_t stream = material == 1 ? options.seed : SplitMix64::stream(options.seed, material)();
      std::vector<Seed> placed =
          reflex_edge_seeds(domain, material, options.radius, options.sharp_angle_degrees, stream);
      std::copy_if(lattice.begin(), lattice.end(), std::back_inserter(placed),
                   [&](const Seed& s) { return s.region == material; });
      for (Seed& s : poisson_disk_seeds(domain, material, options.radius, stream, placed)) all.push_back(s);
    }
    return all;
  });
  for (std::int32_t material = 1; material <= materials; ++material) {
    if (std::none_of(seeds.begin(), seeds.end(), [&](const Seed& s) { return s.region == material; })) {
      throw Error(Error::Kind::InvalidGeometry,
                  c_format("region %d is too thin for a seed %g apart from the others: lower `max_size`", material,
                           options.radius),
                  {.option = "max_size"});
    }
  }
  if (options.mode == InteriorMode::Cvt) phases("cvt", [&] { lloyd_iterations(domain, seeds, options); });
  if (options.before_cells) options.before_cells(seeds);
  Clipping c = clip(domain, seeds, options, &phases);
  return {std::move(c.seeds), std::move(c.cells), c.stats};
}

}  // namespace vorocrust::clipping
