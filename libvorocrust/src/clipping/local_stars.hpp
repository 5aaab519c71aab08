// Internal: the Delaunay tetrahedra about single seeds of one material, computed from each
// seed's Voronoi cell among its neighbours alone, for judging a seed's move without the whole
// mesh (the sliver perturbation of clipped_cells.cpp).
//
// Contract of LocalStars(seeds, domain, reach):
// - Seeds are grouped in a grid of cubes of side `reach`; move(s, p) moves one.
// - star(s, out) appends the tetrahedra (seed indices, ascending, with their smallest dihedral
//   angle in degrees) whose circumcentre is a vertex of s's Voronoi cell among the seeds of its
//   material within `reach`, where that vertex lies inside the material (the tetrahedra
//   dual_tets.hpp reads from the clipped mesh), and the seeds across its faces. It returns false
//   where it cannot be sure: a vertex inside the material with a Delaunay sphere reaching past
//   `reach`, a vertex of more than three faces (cospherical seeds), or a Voro++ cell whose edges
//   disagree. A seed farther than `reach` could still add a vertex inside the material where the
//   local cell has one outside it, at least reach / 2 from s: callers take `reach` above twice
//   the largest Delaunay sphere inside the material (its points' farthest from a seed).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geometry/box_tree.hpp"
#include "geometry/cube_hash.hpp"
#include "seeds/locate_regions.hpp"
#include "vorocrust/seeds.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::clipping {

struct StarTet {
  std::array<std::uint32_t, 4> seeds;  // ascending
  double min_dihedral;
  // A tetrahedron whose seeds stay but one of which moved is another: its shape changed.
  bool operator<(const StarTet& o) const {
    return seeds < o.seeds || (seeds == o.seeds && min_dihedral < o.min_dihedral);
  }
  bool operator==(const StarTet& o) const { return seeds == o.seeds && min_dihedral == o.min_dihedral; }
};

class LocalStars {
 public:
  LocalStars(const std::vector<Seed>& seeds, const SurfaceMesh& domain, double reach);

  void move(std::uint32_t s, const Point& to);
  const Point& position(std::uint32_t s) const { return positions_[s]; }

  [[nodiscard]] bool star(std::uint32_t s, std::vector<StarTet>& out, std::vector<std::uint32_t>& neighbours) const;

 private:
  // Distance from seed s to its material's boundary (cached until s moves): a cell vertex
  // nearer s than that is inside the material without a ray.
  double clearance(std::uint32_t s) const;

  const SurfaceMesh& domain_;
  double reach_;
  std::vector<Point> positions_;
  std::vector<std::int32_t> regions_;
  geometry::CubeHash grid_;
  RegionLocator locate_;
  geometry::BoxTree faces_;
  mutable std::vector<double> clearance_;  // negative: not yet measured
};

}  // namespace vorocrust::clipping
