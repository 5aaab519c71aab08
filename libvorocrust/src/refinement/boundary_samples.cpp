// Supersampling the boundary and querying it (paper appendix A.1, A.2).
#include "refinement/boundary_samples.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "geometry/surface_sampling.hpp"
#include "refinement/point_cloud.hpp"
#include "refinement/subface.hpp"

namespace vorocrust {

namespace {

struct SitePosition {
  const Point& operator()(const SurfaceSite& s) const { return s.position; }
};
using Adaptor = PointCloudAdaptor<SurfaceSite, SitePosition>;
using Tree = StaticKdTree<Adaptor>;

}  // namespace

struct BoundarySamples::Trees {
  Adaptor adaptors[3];
  std::unique_ptr<Tree> trees[3];
};

BoundarySamples::BoundarySamples(const SurfaceMesh& mesh, const Strata& strata, const BoundarySampleCounts& counts,
                                 std::uint64_t seed)
    : trees_(std::make_unique<Trees>()) {
  std::mt19937_64 rng(seed ^ 0x5eed0fb0da41ull);
  std::uniform_real_distribution<double> unit(0.0, 1.0);

  auto& corners = sites_[static_cast<int>(StratumType::Corner)];
  for (Index c = 0; c < strata.corners.size(); ++c) corners.push_back(corner_site(strata, mesh, c));

  // Creases: every edge's midpoint and quarter points, then random points by length.
  auto& crease = sites_[static_cast<int>(StratumType::Crease)];
  const auto crease_point = [&](Index e, double t) {
    const auto [a, b] = strata.topology.edges[e];
    crease.push_back(crease_site(strata, e, (1 - t) * mesh.vertices[a] + t * mesh.vertices[b]));
  };
  std::vector<Index> crease_edges;
  std::vector<double> lengths;
  for (Index e = 0; e < strata.topology.num_edges(); ++e) {
    if (strata.edge_crease[e] == Strata::kNone) continue;
    crease_edges.push_back(e);
    const auto [a, b] = strata.topology.edges[e];
    lengths.push_back((mesh.vertices[b] - mesh.vertices[a]).norm());
    for (double t : {0.125, 0.5, 0.875}) crease_point(e, t);
  }
  // Non-corner vertices on creases belong to the crease.
  for (const Crease& c : strata.creases) {
    for (std::size_t i = 0; i < c.vertices.size(); ++i) {
      if (strata.vertex_corner[c.vertices[i]] != Strata::kNone) continue;
      crease.push_back(crease_site(strata, c.edges[i < c.edges.size() ? i : i - 1], mesh.vertices[c.vertices[i]]));
    }
  }
  if (!crease_edges.empty()) {
    const geometry::WeightedPick pick(lengths);
    const std::size_t n = std::clamp(counts.crease_per_edge * crease_edges.size(), counts.crease_min, counts.crease_max);
    for (std::size_t k = 0; k < n; ++k) {
      const Index e = crease_edges[pick(unit(rng))];
      crease_point(e, unit(rng));
    }
  }

  // Patches: every face's centroid and points near its corners, then random points by area.
  auto& patch = sites_[static_cast<int>(StratumType::Patch)];
  std::vector<double> areas(mesh.num_faces());
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const Point& a = mesh.vertices[mesh.triangles[f][0]];
    const Point& b = mesh.vertices[mesh.triangles[f][1]];
    const Point& c = mesh.vertices[mesh.triangles[f][2]];
    areas[f] = 0.5 * (b - a).cross(c - a).norm();
    patch.push_back(patch_site(strata, f, (a + b + c) / 3));
    patch.push_back(patch_site(strata, f, 0.9 * a + 0.05 * b + 0.05 * c));
    patch.push_back(patch_site(strata, f, 0.05 * a + 0.9 * b + 0.05 * c));
    patch.push_back(patch_site(strata, f, 0.05 * a + 0.05 * b + 0.9 * c));
  }
  if (mesh.num_faces() > 0) {
    const geometry::WeightedPick pick(areas);
    const std::size_t n = std::clamp(counts.patch_per_face * mesh.num_faces(), counts.patch_min, counts.patch_max);
    for (std::size_t k = 0; k < n; ++k) {
      const Index f = static_cast<Index>(pick(unit(rng)));
      const Triangle& t = mesh.triangles[f];
      const Subface face = Subface::triangle(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], f);
      patch.push_back(patch_site(strata, f, face.random_point(rng, unit)));
    }
  }

  for (int t = 0; t < 3; ++t) {
    trees_->adaptors[t].items = &sites_[t];
    trees_->trees[t] = std::make_unique<Tree>(3, trees_->adaptors[t], nanoflann::KDTreeSingleIndexAdaptorParams(16));

  }
}

BoundarySamples::~BoundarySamples() = default;

std::size_t BoundarySamples::size() const { return sites_[0].size() + sites_[1].size() + sites_[2].size(); }

double BoundarySamples::distance_to_non_cosmooth(const SurfaceSite& center, const CoSmoothness& cosmooth,
                                                 double limit) const {
  double best = limit * limit;
  const double query[3] = {center.position.x(), center.position.y(), center.position.z()};
  for (int t = 0; t < 3; ++t) {
    if (sites_[t].empty()) continue;
    const auto& sites = sites_[t];
    FilteredNearest nearest([&](std::uint32_t i) { return !cosmooth(center, sites[i]); }, best);
    trees_->trees[t]->findNeighbors(nearest, query, nanoflann::SearchParams());
    best = std::min(best, nearest.squared_distance());
  }
  return std::sqrt(best);
}

std::vector<std::uint32_t> BoundarySamples::within(StratumType type, const Point& center, double radius) const {
  std::vector<std::uint32_t> found;
  const int t = static_cast<int>(type);
  if (sites_[t].empty()) return found;
  const double query[3] = {center.x(), center.y(), center.z()};
  WithinRadius result(radius * radius, found);
  trees_->trees[t]->findNeighbors(result, query, nanoflann::SearchParams());
  return found;
}

}  // namespace vorocrust
