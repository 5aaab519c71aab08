#include "clipping/local_stars.hpp"

#include <voro++.hh>

#include <algorithm>
#include <cmath>
#include <limits>

#include "cells/raw_cell_extract.hpp"
#include "clipping/dual_tets.hpp"
#include "geometry/nearest_face.hpp"

namespace vorocrust::clipping {

LocalStars::LocalStars(const std::vector<Seed>& seeds, const SurfaceMesh& domain, double reach)
    : domain_(domain),
      reach_(reach),
      grid_(reach),
      locate_(domain),
      faces_(geometry::face_tree(domain)),
      clearance_(seeds.size(), -1) {
  positions_.reserve(seeds.size());
  regions_.reserve(seeds.size());
  for (std::uint32_t s = 0; s < seeds.size(); ++s) {
    positions_.push_back(seeds[s].position);
    regions_.push_back(seeds[s].region);
    grid_.insert(s, seeds[s].position);
  }
}

void LocalStars::move(std::uint32_t s, const Point& to) {
  grid_.move(s, positions_[s], to);
  positions_[s] = to;
  clearance_[s] = -1;
}

double LocalStars::clearance(std::uint32_t s) const {
  if (clearance_[s] < 0) {
    const Point& p = positions_[s];
    const std::int32_t material = regions_[s];
    const auto [face, squared] = geometry::nearest_face(faces_, domain_, p, [&](std::uint32_t f) {
      return geometry::bounds_material(domain_.face_regions[f], material);
    });
    clearance_[s] = face == geometry::BoxTree::kNoItem ? std::numeric_limits<double>::infinity() : std::sqrt(squared);
  }
  return clearance_[s];
}

bool LocalStars::star(std::uint32_t s, std::vector<StarTet>& out, std::vector<std::uint32_t>& neighbours) const {
  const Point& p = positions_[s];
  // Voro++ works in the unit box: the cut vectors are scaled by 1 / reach.
  voro::voronoicell_neighbor cell;
  cell.init(-1, 1, -1, 1, -1, 1);
  // Nearest first: Voro++ then cuts the far ones off with a glance.
  std::vector<std::pair<double, std::uint32_t>> near;
  grid_.near(p, p, [&](std::uint32_t w) {
    if (w == s || regions_[w] != regions_[s]) return;
    const double d2 = (positions_[w] - p).squaredNorm() / (reach_ * reach_);
    if (d2 < 1) near.emplace_back(d2, w);
  });
  std::sort(near.begin(), near.end());
  for (const auto& [d2, w] : near) {
    const Point d = (positions_[w] - p) / reach_;
    cell.nplane(d.x(), d.y(), d.z(), d2, static_cast<int>(w));
  }
  if (!cells::edges_consistent(cell)) return false;
  std::vector<double> xyz;
  std::vector<int> faces, ids;
  cell.vertices(0, 0, 0, xyz);
  cell.face_vertices(faces);
  cell.neighbors(ids);
  // Each vertex's faces' seeds.
  const std::size_t n = xyz.size() / 3;
  std::vector<std::array<int, 3>> around(n, {-1, -1, -1});
  std::vector<int> count(n, 0);
  for (std::size_t f = 0, at = 0; f < ids.size(); ++f) {
    const int size = faces[at];
    if (ids[f] >= 0) neighbours.push_back(static_cast<std::uint32_t>(ids[f]));
    for (int k = 1; k <= size; ++k) {
      const auto v = static_cast<std::size_t>(faces[at + static_cast<std::size_t>(k)]);
      if (count[v] < 3) around[v][static_cast<std::size_t>(count[v])] = ids[f];
      ++count[v];
    }
    at += static_cast<std::size_t>(size) + 1;
  }
  for (std::size_t v = 0; v < n; ++v) {
    const Point offset = reach_ * Point(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
    const double r = offset.norm();
    const Point vertex = p + offset;
    if (r >= clearance(s) && locate_.region_of(vertex) != regions_[s]) continue;
    // Inside the material: the tetrahedron is sure when every seed within its sphere's reach was cut.
    if (count[v] != 3 || 2 * r >= reach_ || std::min({around[v][0], around[v][1], around[v][2]}) < 0) return false;
    StarTet t{{s, static_cast<std::uint32_t>(around[v][0]), static_cast<std::uint32_t>(around[v][1]),
               static_cast<std::uint32_t>(around[v][2])},
              0};
    std::sort(t.seeds.begin(), t.seeds.end());
    t.min_dihedral =
        tet_shape(positions_[t.seeds[0]], positions_[t.seeds[1]], positions_[t.seeds[2]], positions_[t.seeds[3]])
            .min_dihedral;
    out.push_back(t);
  }
  return true;
}

}  // namespace vorocrust::clipping
