#include "clipping/clipped_cells.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <optional>

#include "clipping/dual_tets.hpp"
#include "clipping/edge_seeds.hpp"
#include "clipping/local_stars.hpp"
#include "clipping/poisson_disk_seeds.hpp"
#include "core/c_format.hpp"
#include "core/split_mix.hpp"
#include "core/surface_measures.hpp"
#include "geometry/box_tree.hpp"
#include "geometry/nearest_face.hpp"
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
    const std::uint32_t face = geometry::nearest_face(tree_, domain_, p, [&](std::uint32_t f) {
      return geometry::bounds_material(domain_.face_regions[f], material);
    }).first;
    if (face == geometry::BoxTree::kNoItem) return p;
    Point inward = face_normal(domain_, face);
    if (domain_.face_regions[face].back == material) inward = -inward;
    return geometry::closest_on_face(domain_, face, p) + inset * inward;
  }

 private:
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
// of other kinds (on reflex edges) stay where they are. Returns which seeds it holds on the surface.
std::vector<char> lloyd_iterations(const SurfaceMesh& domain, std::vector<Seed>& seeds, const ClippedOptions& options) {
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
  return held;
}

// The dual tetrahedra of one clipping (dual_tets.hpp) by their seeds, with their smallest
// dihedral angles, and the largest of their circumspheres.
struct SeedStars {
  std::vector<std::array<std::uint32_t, 4>> tets;
  std::vector<double> min_dihedral;
  double largest_circumradius = 0;

  explicit SeedStars(const VoronoiMesh& cells) {
    for (const std::array<std::uint32_t, 4>& t : dual_tets(cells).tets) {
      std::array<std::uint32_t, 4> s;
      for (int k = 0; k < 4; ++k) s[k] = static_cast<std::uint32_t>(cells.cells[t[k]].seed);
      const auto at = [&](int k) -> const Point& { return cells.cells[t[k]].site; };
      const TetShape shape = tet_shape(at(0), at(1), at(2), at(3));
      min_dihedral.push_back(shape.min_dihedral);
      largest_circumradius = std::max(largest_circumradius, shape.circumradius);
      tets.push_back(s);
    }
  }
};

// The tetrahedra about the seeds `around` (LocalStars::star), each once; false where one star is
// not sure.
bool stars_of(const LocalStars& local, const std::vector<std::uint32_t>& around, std::vector<StarTet>& tets) {
  tets.clear();
  std::vector<std::uint32_t> ignored;
  for (std::uint32_t u : around) {
    if (!local.star(u, tets, ignored)) return false;
  }
  std::sort(tets.begin(), tets.end());
  tets.erase(std::unique(tets.begin(), tets.end()), tets.end());
  return true;
}

// The smallest angle of the tetrahedra in `before` but not in `after` (what a move removes; 180
// for none). Both sorted.
double worst_removed(const std::vector<StarTet>& before, const std::vector<StarTet>& after) {
  std::vector<StarTet> removed;
  std::set_difference(before.begin(), before.end(), after.begin(), after.end(), std::back_inserter(removed));
  double worst = 180;
  for (const StarTet& t : removed) worst = std::min(worst, t.min_dihedral);
  return worst;
}

// Yan et al.'s post-processing of the dual tetrahedra (their 5.2, after Tournois, Srinivasan and
// Alliez's sliver perturbation, with random moves as Edelsbrunner and Guoy's): a seed of each
// sliver tries small moves in random directions (a seed held on the surface slides along it), and
// takes the first whose new tetrahedra have a larger smallest angle than those it removes. Moves
// are judged from the seeds' Voronoi cells among their neighbours (local_stars.hpp), so that a try
// costs a few dozen cells; each round clips the whole mesh once, to find the slivers left.
SliverPerturbation perturb_slivers(const SurfaceMesh& domain, std::vector<Seed>& seeds, const std::vector<char>& held,
                                   const ClippedOptions& options) {
  constexpr int kMaxRounds = 30, kIdleRounds = 3, kTries = 16;
  SliverPerturbation stats;
  const RegionLocator locate(domain);
  const MaterialBoundary boundary(domain);
  std::optional<LocalStars> local;  // its reach from the first clipping's tetrahedra
  const std::size_t n = seeds.size();
  const auto movable = [&](std::uint32_t v) {
    return seeds[v].kind == SeedKind::Interior || (v < held.size() && held[v]);
  };
  std::vector<StarTet> before, after, own;
  for (int idle = 0; stats.rounds < kMaxRounds && idle < kIdleRounds; ++stats.rounds) {
    const SeedStars mesh(clip(domain, seeds, options, nullptr).cells);
    std::vector<std::uint32_t> slivers;
    for (std::uint32_t t = 0; t < mesh.tets.size(); ++t) {
      if (mesh.min_dihedral[t] < options.sliver_angle) slivers.push_back(t);
    }
    if (stats.rounds == 0) stats.slivers_before = slivers.size();
    if (slivers.empty()) break;
    // Moves change the spheres by a fraction of an edge: 2.5 times the largest covers twice it.
    if (!local) local.emplace(seeds, domain, 2.5 * mesh.largest_circumradius);
    std::stable_sort(slivers.begin(), slivers.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return mesh.min_dihedral[a] < mesh.min_dihedral[b]; });
    SplitMix64 random = SplitMix64::stream(options.seed, 0x5113e7 + static_cast<std::uint64_t>(stats.rounds));
    std::vector<char> changed(n, 0);  // seeds whose tetrahedra a kept move changed
    std::size_t kept = 0;
    for (std::uint32_t t : slivers) {
      const std::array<std::uint32_t, 4>& tet = mesh.tets[t];
      if (std::any_of(tet.begin(), tet.end(), [&](std::uint32_t v) { return changed[v]; })) continue;
      std::array<std::uint32_t, 4> free{};
      int count = 0;
      for (std::uint32_t v : tet) {
        if (movable(v)) free[count++] = v;
      }
      if (count == 0) continue;
      double edges = 0;
      for (int i = 0; i < 4; ++i) {
        for (int j = i + 1; j < 4; ++j) edges += (seeds[tet[i]].position - seeds[tet[j]].position).norm() / 6;
      }
      for (int attempt = 0; attempt < kTries; ++attempt) {
        const std::uint32_t v = free[random() % static_cast<std::uint64_t>(count)];
        Point direction = Point::Zero();
        while (direction.squaredNorm() < 1e-4 || direction.squaredNorm() > 0.25) {
          direction = Point(random.unit(), random.unit(), random.unit()) - Point::Constant(0.5);
        }
        Seed& s = seeds[v];
        const Point from = s.position;
        const Point step = (0.05 + 0.2 * random.unit()) * edges * direction.normalized();
        const Point to = v < held.size() && held[v] ? boundary.onto(from + step, s.region, kJitter * options.radius)
                                                    : Point(from + step);
        if (locate.region_of(to) != s.region) continue;
        ++stats.moves_tried;
        // The seeds whose tetrahedra the move can change: v and its neighbours before and after.
        std::vector<std::uint32_t> around{v};
        own.clear();
        if (!local->star(v, own, around)) continue;
        local->move(v, to);
        const bool sure = local->star(v, own, around);
        std::sort(around.begin(), around.end());
        around.erase(std::unique(around.begin(), around.end()), around.end());
        if (!sure || !stars_of(*local, around, after)) {
          local->move(v, from);
          continue;
        }
        local->move(v, from);
        if (!stars_of(*local, around, before)) continue;
        if (worst_removed(after, before) > worst_removed(before, after)) {
          local->move(v, to);
          s.position = to;
          for (std::uint32_t u : around) changed[u] = 1;
          ++kept;
          break;
        }
      }
    }
    stats.moves_kept += kept;
    idle = kept == 0 ? idle + 1 : 0;
  }
  return stats;
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
  std::vector<char> held;
  if (options.mode == InteriorMode::Cvt) held = phases("cvt", [&] { return lloyd_iterations(domain, seeds, options); });
  SliverPerturbation perturbation;
  if (options.sliver_angle > 0) {
    perturbation = phases("sliver perturbation", [&] { return perturb_slivers(domain, seeds, held, options); });
  }
  if (options.before_cells) options.before_cells(seeds);
  Clipping c = clip(domain, seeds, options, &phases);
  if (options.sliver_angle > 0) {
    const SeedStars final(c.cells);
    perturbation.slivers_after = static_cast<std::size_t>(std::count_if(
        final.min_dihedral.begin(), final.min_dihedral.end(), [&](double a) { return a < options.sliver_angle; }));
  }
  c.stats.slivers = perturbation;
  return {std::move(c.seeds), std::move(c.cells), c.stats};
}

}  // namespace vorocrust::clipping
