// Supersampling the boundary and querying it (paper appendix A.1, A.2).
#include "refinement/boundary_samples.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/split_mix.hpp"
#include "geometry/box_tree.hpp"
#include "geometry/closest_point.hpp"
#include "geometry/surface_sampling.hpp"
#include "geometry/point_cloud.hpp"
#include "refinement/subface.hpp"

namespace vorocrust {

namespace {

struct SitePosition {
  const Point& operator()(const SurfaceSite& s) const { return s.position; }
};
using Adaptor = PointCloudAdaptor<SurfaceSite, SitePosition>;
using Tree = StaticKdTree<Adaptor>;

// How many random samples an element gets: their expected number, rounded up or down by a
// uniform number u so that the expectation stays exact. Random points in proportion to measure,
// stratified by element.
std::size_t share_of(double expected, double u) {
  const double whole = std::floor(expected);
  return static_cast<std::size_t>(whole) + (u < expected - whole ? 1 : 0);
}

}  // namespace

// Patch samples of one face, few enough to scan.
struct SampleGroup {
  Index face;
  std::uint32_t begin, end;  // a range of the patch samples
};

// Corner and crease samples in k-d trees; patch samples, by far the most, in groups of one face
// under a bounding-volume hierarchy, so that a query can pass over whole faces at once.
struct BoundarySamples::Trees {
  Adaptor adaptors[2];
  std::unique_ptr<Tree> trees[2];  // corner, crease
  std::vector<SampleGroup> groups;
  std::unique_ptr<geometry::BoxTree> group_tree;  // over the groups' boxes
  std::vector<SurfaceSite> face_sites;            // per face, the site of a point of its plane
  std::vector<std::array<Point, 3>> face_corners;  // per face
};

namespace {

constexpr std::size_t kGroupSize = 32;         // patch samples per group, about
constexpr std::size_t kMaxPiecesPerFace = 4096;  // a face holding a million samples: 256 a group

}  // namespace

BoundarySamples::BoundarySamples(const SurfaceMesh& mesh, const Strata& strata, const BoundarySampleCounts& counts,
                                 std::uint64_t seed)
    : trees_(std::make_unique<Trees>()) {
  std::mt19937_64 rng(seed ^ 0x5eed0fb0da41ull);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto& corners = sites_[static_cast<int>(StratumType::Corner)];
  for (Index c = 0; c < strata.corners.size(); ++c) corners.push_back(corner_site(strata, mesh, c));
  add_crease_samples(mesh, strata, counts, rng, unit);
  for (int t = 0; t < 2; ++t) {
    trees_->adaptors[t].items = &sites_[t];
    trees_->trees[t] = std::make_unique<Tree>(3, trees_->adaptors[t], nanoflann::KDTreeSingleIndexAdaptorParams(16));
  }
  add_patch_samples(mesh, strata, counts, seed ^ 0x9a7c4f1e5b3d2a01ull);
}

// Every crease edge's midpoint and quarter points, every non-corner vertex on a crease, then
// random points by length.
void BoundarySamples::add_crease_samples(const SurfaceMesh& mesh, const Strata& strata, const BoundarySampleCounts& counts,
                                         std::mt19937_64& rng, std::uniform_real_distribution<double>& unit) {
  auto& crease = sites_[static_cast<int>(StratumType::Crease)];
  const auto crease_point = [&](Index e, double t) {
    const auto [a, b] = strata.topology.edges[e];
    crease.push_back(crease_site(strata, e, (1 - t) * mesh.vertices[a] + t * mesh.vertices[b]));
  };
  std::vector<Index> crease_edges;
  std::vector<double> lengths;
  double total_length = 0;
  for (Index e = 0; e < strata.topology.num_edges(); ++e) {
    if (strata.edge_crease[e] == Strata::kNone) continue;
    crease_edges.push_back(e);
    const auto [a, b] = strata.topology.edges[e];
    total_length += lengths.emplace_back((mesh.vertices[b] - mesh.vertices[a]).norm());
    for (double t : {0.125, 0.5, 0.875}) crease_point(e, t);
  }
  for (const Crease& c : strata.creases) {
    for (std::size_t i = 0; i < c.vertices.size(); ++i) {
      if (strata.vertex_corner[c.vertices[i]] != Strata::kNone) continue;
      crease.push_back(crease_site(strata, c.edges[i < c.edges.size() ? i : i - 1], mesh.vertices[c.vertices[i]]));
    }
  }
  if (!(total_length > 0)) return;
  const auto n = static_cast<double>(
      std::clamp(counts.crease_per_edge * crease_edges.size(), counts.crease_min, counts.crease_max));
  for (std::size_t k = 0; k < crease_edges.size(); ++k) {
    for (std::size_t i = share_of(n * lengths[k] / total_length, unit(rng)); i > 0; --i) crease_point(crease_edges[k], unit(rng));
  }
}

// Every face's centroid and points near its corners, then random points by area, stratified:
// the face is quartered (as the refinement's pool quarters it) until each piece's share is at
// most a few groups' worth, and each piece gets its share of uniform points; a piece's points
// form a group and the fixed points one more. Faces are sampled in parallel, each from its own
// random stream, so the samples do not depend on the thread count: once to count them, once to
// write them where the counts put them.
void BoundarySamples::add_patch_samples(const SurfaceMesh& mesh, const Strata& strata, const BoundarySampleCounts& counts,
                                        std::uint64_t seed) {
  const std::size_t faces = mesh.num_faces();
  std::vector<double> areas(faces);
  double total_area = 0;
  for (Index f = 0; f < faces; ++f) {
    const Triangle& t = mesh.triangles[f];
    total_area += areas[f] = 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).norm();
  }
  const auto n = static_cast<double>(std::clamp(counts.patch_per_face * faces, counts.patch_min, counts.patch_max));
  constexpr std::size_t kFixed = 4;
  // Face f's pieces and how many random points each gets, from its stream; the stream is then
  // where its points start.
  const auto plan = [&](Index f, std::vector<Subface>& pieces, std::vector<std::size_t>& shares, std::vector<Subface>& next) {
    SplitMix64 random = SplitMix64::stream(seed, f);
    pieces.clear();
    shares.clear();
    if (!(total_area > 0)) return random;
    const std::size_t wanted = share_of(n * areas[f] / total_area, random.unit());
    const Triangle& t = mesh.triangles[f];
    pieces.assign(1, Subface::triangle(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], f));
    for (std::size_t share = wanted; share > 2 * kGroupSize && pieces.size() < kMaxPiecesPerFace; share /= 4) {
      next.clear();
      for (const Subface& piece : pieces) {
        for (const Subface& child : piece.split()) next.push_back(child);
      }
      pieces.swap(next);
    }
    const double per_piece = static_cast<double>(wanted) / static_cast<double>(pieces.size());
    for (std::size_t k = 0; k < pieces.size(); ++k) shares.push_back(share_of(per_piece, random.unit()));
    return random;
  };
  struct Scratch {
    std::vector<Subface> pieces, next;
    std::vector<std::size_t> shares;
  };
  // first_point[f], first_group[f]: where face f's samples and groups go.
  std::vector<std::size_t> first_point(faces + 1, 0), first_group(faces + 1, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, faces, 256), [&](const auto& range) {
    Scratch w;
    for (std::size_t f = range.begin(); f != range.end(); ++f) {
      plan(static_cast<Index>(f), w.pieces, w.shares, w.next);
      first_point[f + 1] = kFixed;
      first_group[f + 1] = 1;
      for (std::size_t share : w.shares) first_point[f + 1] += share, first_group[f + 1] += share > 0;
    }
  });
  for (std::size_t f = 0; f < faces; ++f) first_point[f + 1] += first_point[f], first_group[f + 1] += first_group[f];
  patch_points_.resize(first_point[faces]);
  trees_->groups.resize(first_group[faces]);
  std::vector<geometry::Box> boxes(first_group[faces]);
  trees_->face_sites.resize(faces);
  trees_->face_corners.resize(faces);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, faces, 256), [&](const auto& range) {
    Scratch w;
    for (std::size_t f = range.begin(); f != range.end(); ++f) {
      const Triangle& t = mesh.triangles[f];
      const Point &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
      trees_->face_sites[f] = patch_site(strata, static_cast<Index>(f), a);
      trees_->face_corners[f] = {a, b, c};
      std::size_t point = first_point[f], group = first_group[f];
      const auto close_group = [&](std::size_t begin) {
        geometry::Box& box = boxes[group];
        for (std::size_t i = begin; i < point; ++i) box.include(patch_points_[i]);
        trees_->groups[group++] = {static_cast<Index>(f), static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(point)};
      };
      for (const Point& p : {Point((a + b + c) / 3), Point(0.9 * a + 0.05 * b + 0.05 * c),
                             Point(0.05 * a + 0.9 * b + 0.05 * c), Point(0.05 * a + 0.05 * b + 0.9 * c)}) {
        patch_points_[point++] = p;
      }
      close_group(point - kFixed);
      SplitMix64 random = plan(static_cast<Index>(f), w.pieces, w.shares, w.next);
      for (std::size_t k = 0; k < w.pieces.size(); ++k) {
        if (w.shares[k] == 0) continue;
        const Subface& piece = w.pieces[k];
        const std::size_t begin = point;
        for (std::size_t i = 0; i < w.shares[k]; ++i) {
          const double u = random.unit();
          patch_points_[point++] = geometry::point_in_triangle(piece.corner(0), piece.corner(1), piece.corner(2), u, random.unit());
        }
        close_group(begin);
      }
    }
  });
  std::vector<std::uint32_t> items(trees_->groups.size());
  for (std::uint32_t i = 0; i < items.size(); ++i) items[i] = i;
  trees_->group_tree = std::make_unique<geometry::BoxTree>(std::move(boxes), std::move(items));
}

BoundarySamples::~BoundarySamples() = default;

std::size_t BoundarySamples::size() const { return sites_[0].size() + sites_[1].size() + patch_points_.size(); }

double BoundarySamples::distance_to_non_cosmooth(const SurfaceSite& center, const CoSmoothness& cosmooth,
                                                 double limit) const {
  double best = limit * limit;
  const double query[3] = {center.position.x(), center.position.y(), center.position.z()};
  for (int t = 0; t < 2; ++t) {
    if (sites_[t].empty()) continue;
    const auto& sites = sites_[t];
    FilteredNearest nearest([&](std::uint32_t i) { return !cosmooth(center, sites[i]); }, best);
    trees_->trees[t]->findNeighbors(nearest, query, nanoflann::SearchParams());
    best = std::min(best, nearest.squared_distance());
  }
  nearest_non_cosmooth_patch_sample(center, cosmooth, best);
  return std::sqrt(best);
}

// The filtered search over the patch samples, one face at a time: a group is skipped when every
// sample in it lies beyond the face's non-co-smooth reach (most faces near a centre lie in its own
// patch and bend too little to hold a point that is not co-smooth with it). A face none of whose
// points is co-smooth with the centre (a patch that does not meet its stratum) needs no samples:
// its nearest point is exact, where samples would miss a face folding back within a thin wedge
// at a corner until the balls the estimate let grow too large had to shrink.
void BoundarySamples::nearest_non_cosmooth_patch_sample(const SurfaceSite& center, const CoSmoothness& cosmooth,
                                                        double& best) const {
  if (!trees_->group_tree || !(best > 0)) return;
  const Point& p = center.position;
  // Nodes no nearer than the best so far are passed over. (A cube of side twice the first bound
  // was searched before: on a smooth patch the nearest point that is not co-smooth lies far, and
  // the cube held most of the model, igl_bunny --smooth.) Every group passed over would have
  // failed the test below too, as the best only falls, and the rest come in the same order; only
  // a group whose box meets the bound to within a rounding of the cube's side can now be looked
  // at where the cube missed it.
  const auto nearer = [&](const geometry::Box& box) { return box.squared_distance(p) < best; };
  trees_->group_tree->for_each_where(nearer, [&](std::uint32_t g) {
    const SampleGroup& group = trees_->groups[g];
    const geometry::Box& box = trees_->group_tree->box(g);
    SurfaceSite x = trees_->face_sites[group.face];
    const double reach = cosmooth.non_cosmooth_reach(center, group.face, x.position);
    const double gap2 = (p - p.cwiseMax(box.lo).cwiseMin(box.hi)).squaredNorm();
    if (!(gap2 < best) || !(gap2 < reach * reach)) return;
    if (reach == std::numeric_limits<double>::infinity()) {
      const auto& t = trees_->face_corners[group.face];
      best = std::min(best, (geometry::closest_on_triangle(p, t[0], t[1], t[2]) - p).squaredNorm());
      return;
    }
    for (std::uint32_t i = group.begin; i < group.end; ++i) {
      x.position = patch_points_[i];
      const double d2 = (x.position - p).squaredNorm();
      if (d2 < best && !cosmooth(center, x)) best = d2;
    }
  });
}

}  // namespace vorocrust
