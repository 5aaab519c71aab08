// Seeds that repair the cells: where a face stays highly skew, and where a cell is too long.
#include "cells/repair_seeds.hpp"

#include <memory>

#include "interior/sphere_seeds.hpp"

namespace vorocrust {

using namespace interior;

std::vector<Seed> skew_repair_seeds(const std::vector<cells::CutFace>& skew, const std::vector<Seed>& seeds,
                                    const BallIndex& balls, const RegionLocator& regions,
                                    const std::vector<Seed>& placed) {
  SphereSeeds place(balls, regions, placed);
  std::vector<Seed> added;
  std::vector<std::uint32_t> a, b;
  // The directions from a sphere's centre of the seeds of `region` on it, through a tree of the
  // seeds made when first needed.
  const SeedCloud cloud{&seeds};
  std::unique_ptr<StaticKdTree<SeedCloud>> seed_tree;
  std::vector<std::uint32_t> near;
  const auto on_sphere = [&](const Point& centre, double r, std::int32_t region) {
    if (!seed_tree) seed_tree = std::make_unique<StaticKdTree<SeedCloud>>(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
    points_within(*seed_tree, centre, r * r * (1 + 1e-6), near);
    std::vector<Point> out;
    for (std::uint32_t i : near) {
      if (seeds[i].region == region && on_sphere_of(seeds[i].position, centre, r)) out.push_back((seeds[i].position - centre) / r);
    }
    return out;
  };
  // One face's repair with the room given; whether it placed a seed.
  const auto repair = [&](const cells::CutFace& face, const Room& room) {
    const Seed &s = seeds[face.owner_seed], &t = seeds[static_cast<std::size_t>(face.neighbour_seed)];
    const std::int32_t region = s.region;
    const FaceGeometry& g = face.geometry;
    // A seed at `target`, pushed out of the balls near it, if it stays nearer the target than
    // `from` (a seed of the face) is: it takes the part of the cells about the target.
    const auto place_near = [&](const Point& target, const Point& from) {
      const std::optional<Seed> seed =
          place.place_split(target, from, region, g.normal, room, [](const Point&, double) { return true; });
      if (seed) added.push_back(*seed);
      return seed.has_value();
    };
    // The cell whose centroid lies farther from its seed split at its centroid: that draws the
    // centroid back toward the seed, and the link between the two centroids back through the face.
    const auto split_farther = [&] {
      const bool owner_farther = (face.owner_centroid - s.position).norm() >= (face.neighbour_centroid - t.position).norm();
      return owner_farther ? place_near(face.owner_centroid, s.position) : place_near(face.neighbour_centroid, t.position);
    };
    // Two seeds on spheres (poles, repairs) have cells squeezed between the balls; a seed on yet
    // another sphere makes one more such cell beside them (where openmeeg_HeadNNa1's south half
    // crosses its skull, rounds of them never ended), so these are split first.
    if (s.kind == SeedKind::Cap && t.kind == SeedKind::Cap && split_farther()) return true;
    spheres_through(balls, s.position, s.radius, a);
    spheres_through(balls, t.position, t.radius, b);
    // A narrow wedge through the centre of a sphere both seeds lie on, between seeds there that
    // are nearly cocircular: near the centre every cell of a seed on the sphere is a cone over
    // its part of the sphere. A seed on the sphere toward the face takes the cones' corner there
    // (igl_bunny's big corner balls, with their seeds spread all round). Where that point lies in
    // other balls, as about a sphere whose seeds spread round it in arcs either side of a smaller
    // ball (and which then has no pole), a seed at the free point of the sphere farthest from
    // them replaces the wedge's neighbours by itself.
    for (std::uint32_t q : a) {
      const Point& centre = balls[q].site.position;
      const double r = balls[q].radius;
      if (!std::binary_search(b.begin(), b.end(), q) || !((g.centroid - centre).norm() < kNearCentre * r)) continue;
      const Point towards = g.centroid - centre;
      std::optional<Seed> seed;
      if (towards.norm() > 0) seed = place.place(q, towards.normalized(), region, kCloseSpacing, room);
      if (!seed) seed = place.place_far_from(q, on_sphere(centre, r, region), region, room);
      if (seed) {
        added.push_back(*seed);
        return true;
      }
    }
    // The spheres either seed lies on, those of both first (their centres lie on the face's
    // plane), nearest to the face first; the first that takes a seed toward the face.
    std::vector<std::pair<double, std::uint32_t>> candidates;
    for (const auto* list : {&a, &b}) {
      for (std::uint32_t q : *list) {
        const bool both = std::binary_search(a.begin(), a.end(), q) && std::binary_search(b.begin(), b.end(), q);
        if (!both && list == &b && std::binary_search(a.begin(), a.end(), q)) continue;  // listed once
        candidates.emplace_back((both ? 0 : 1e300) + (balls[q].site.position - g.centroid).norm(), q);
      }
    }
    std::sort(candidates.begin(), candidates.end());
    for (const auto& [order, q] : candidates) {
      const Point towards = g.centroid - balls[q].site.position;
      if (!(towards.norm() > 0)) continue;
      // A face near the centre is a sliver about it (a seed just off the sphere moved the shared
      // vertex there): it needs the seed toward it, however close the seeds already placed.
      const double spacing = towards.norm() < kNearCentre * balls[q].radius ? kCloseSpacing : 1;
      if (const std::optional<Seed> seed = place.place(q, towards.normalized(), region, spacing, room)) {
        added.push_back(*seed);
        return true;
      }
    }
    // No sphere takes one (a face between two seeds on no common sphere, often one a repair
    // seed): a seed at the face's centroid takes the small face's corner of both cells.
    if (place_near(g.centroid, s.position)) return true;
    // No seed may go near the face either (it lies inside a ball).
    return split_farther();
  };
  for (const cells::CutFace& face : skew) {
    if (!face.between_cells) continue;
    if (seeds[face.owner_seed].region != seeds[static_cast<std::size_t>(face.neighbour_seed)].region) continue;
    if (!repair(face, kRoom)) repair(face, kTightRoom);
  }
  return added;
}

std::vector<Seed> aspect_split_seeds(const std::vector<cells::LongCell>& long_cells, const std::vector<Seed>& seeds,
                                     const BallIndex& balls, const RegionLocator& regions,
                                     const std::vector<Seed>& placed) {
  SphereSeeds place(balls, regions, placed);
  const SeedCloud cloud{&seeds};
  const StaticKdTree<SeedCloud> tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  std::vector<std::uint32_t> near;
  geometry::BallTree splits;  // those placed here, each with kSplitApart of its reach
  const auto apart = [&](const Point& p, double reach) {
    const double gap = kSplitApart * reach;
    points_within(tree, p, gap * gap, near);
    return near.empty() && !splits.contains(p);
  };
  std::vector<Seed> added;
  for (const cells::LongCell& cell : long_cells) {
    const Seed& own = seeds[cell.seed];
    // At the centroid; where that lies in a ball and the push out of it goes farther than the
    // seed is, halfway on to the far tip, where the seed is farther and the push may be shorter
    // (on igl_bunny, fertility and sandia_bracket this splits 70, 15 and 16 cells more, and the
    // cells above 5 fall from 3055, 1428 and 252 to 3006, 1416 and 244).
    for (const Point& target : {cell.centroid, Point((cell.centroid + cell.tip) / 2)}) {
      if (const std::optional<Seed> seed =
              place.place_split(target, own.position, own.region, target - own.position, kSplitRoom, apart)) {
        splits.insert(seed->position, kSplitApart * seed->radius, static_cast<std::uint32_t>(added.size()));
        added.push_back(*seed);
        break;
      }
    }
  }
  return added;
}


}  // namespace vorocrust
