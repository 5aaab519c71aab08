#include "clipping/edge_seeds.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "core/edge_topology.hpp"
#include "core/surface_measures.hpp"
#include "core/split_mix.hpp"
#include "geometry/cube_hash.hpp"
#include "seeds/locate_regions.hpp"

namespace vorocrust::clipping {
namespace {

constexpr double kInset = 1e-3;

// The points of the edge seeds placed so far, hashed by cubes of side r_e: those within r_e of
// a point lie in the 27 cubes about it.
struct PlacedPoints {
  explicit PlacedPoints(double side) : hash(side) {}
  void add(const Point& p) {
    hash.insert(static_cast<std::uint32_t>(points.size()), p);
    points.push_back(p);
  }
  template <class Visit>
  void near(const Point& lo, const Point& hi, Visit&& visit) const {
    hash.near(lo, hi, [&](std::uint32_t i) { visit(points[i]); });
  }
  geometry::CubeHash hash;
  std::vector<Point> points;
};

// The parts of segment [a, b], as parameters in [0, 1], farther than r from every seed.
std::vector<std::pair<double, double>> open_parts(const Point& a, const Point& b, double r, const PlacedPoints& seeds) {
  const Point d = b - a;
  const double length2 = d.squaredNorm();
  std::vector<std::pair<double, double>> covered;
  seeds.near(a.cwiseMin(b), a.cwiseMax(b), [&](const Point& s) {
    // |a + t d - s|^2 < r^2: a quadratic in t.
    const Point f = a - s;
    const double half_b = f.dot(d), c = f.squaredNorm() - r * r;
    const double disc = half_b * half_b - length2 * c;
    if (disc <= 0) return;
    const double root = std::sqrt(disc);
    const double lo = (-half_b - root) / length2, hi = (-half_b + root) / length2;
    if (hi > 0 && lo < 1) covered.emplace_back(std::max(lo, 0.0), std::min(hi, 1.0));
  });
  std::sort(covered.begin(), covered.end());
  std::vector<std::pair<double, double>> open;
  double at = 0;
  for (const auto& [lo, hi] : covered) {
    if (lo > at) open.emplace_back(at, lo);
    at = std::max(at, hi);
  }
  if (at < 1) open.emplace_back(at, 1.0);
  return open;
}

}  // namespace

std::vector<Seed> reflex_edge_seeds(const SurfaceMesh& domain, std::int32_t material, double radius,
                                    double sharp_angle_degrees, std::uint64_t seed) {
  const EdgeTopology topology = build_edge_topology(domain);
  const double cos_sharp = std::cos(sharp_angle_degrees * std::numbers::pi / 180);
  const auto bounds = [&](Index f) {
    const RegionPair& r = domain.face_regions[f];
    return (r.back == material) != (r.front == material);
  };
  // Out of the material: a face's normal points to its front.
  const auto outward = [&](Index f) {
    const Point n = face_normal(domain, f);
    return domain.face_regions[f].back == material ? n : Point(-n);
  };
  std::vector<std::size_t> reflex;
  for (std::size_t e = 0; e < topology.num_edges(); ++e) {
    std::vector<Index> faces;
    for (Index f : topology.faces_of(e)) {
      if (bounds(f)) faces.push_back(f);
    }
    if (faces.size() != 2) continue;
    const Point n0 = outward(faces[0]), n1 = outward(faces[1]);
    if (n0.dot(n1) > cos_sharp) continue;
    const Triangle& t1 = domain.triangles[faces[1]];
    const auto [u, w] = topology.edges[e];
    const Index far = t1[0] != u && t1[0] != w ? t1[0] : (t1[1] != u && t1[1] != w ? t1[1] : t1[2]);
    if (n0.dot(domain.vertices[far] - domain.vertices[u]) > 0) reflex.push_back(e);
  }
  // Each seed's way into the material: against the outward normals of the reflex faces at its edge
  // or end.
  std::vector<Point> inward_at_vertex(domain.vertices.size(), Point::Zero());
  std::vector<Point> inward_at_edge(topology.num_edges(), Point::Zero());
  for (std::size_t e : reflex) {
    for (Index f : topology.faces_of(e)) {
      if (bounds(f)) inward_at_edge[e] -= outward(f);
    }
  }
  // An end's way in: against every face of the material about it (at a reflex edge's end on a
  // flat side, the edge's faces alone would keep it on that side).
  std::vector<char> is_end(domain.vertices.size(), 0);
  for (std::size_t e : reflex) is_end[topology.edges[e][0]] = is_end[topology.edges[e][1]] = 1;
  for (Index f = 0; f < domain.num_faces(); ++f) {
    if (!bounds(f)) continue;
    for (Index v : domain.triangles[f]) {
      if (is_end[v]) inward_at_vertex[v] -= outward(f);
    }
  }
  const double r_e = radius / std::sqrt(2.0);
  PlacedPoints placed(r_e);
  std::vector<Seed> seeds;
  const RegionLocator locate(domain);
  // A seed exactly on the surface would put Voronoi vertices on it, ties the clipping's side tests
  // cannot settle: each moves into the material by a thousandth of r_e, which keeps its edge within
  // its cell up to that much.
  SplitMix64 jitter = SplitMix64::stream(seed, topology.num_edges());
  const auto add = [&](const Point& p, const Point& inward) {
    // The way in turned a little at random: an end's way in may lie in a side's plane, and a
    // seed in the plane of input faces meets their bisectors in ties.
    const Point turn(jitter.unit() - 0.5, jitter.unit() - 0.5, jitter.unit() - 0.5);
    const Point q = p + kInset * r_e * (inward.normalized() + 0.5 * turn).normalized();
    if (locate.region_of(q) != material) return false;
    placed.add(p);
    seeds.push_back({q, material, r_e, SeedKind::Surface});
    return true;
  };
  std::vector<char> ends(domain.vertices.size(), 0);
  for (std::size_t e : reflex) {
    for (Index v : topology.edges[e]) {
      if (!ends[v]) {
        ends[v] = 1;
        bool near = false;
        placed.near(domain.vertices[v], domain.vertices[v],
                    [&](const Point& s) { near = near || (s - domain.vertices[v]).squaredNorm() < r_e * r_e; });
        if (!near) add(domain.vertices[v], inward_at_vertex[v]);
      }
    }
  }
  for (std::size_t e : reflex) {
    SplitMix64 random = SplitMix64::stream(seed, e);
    const Point& a = domain.vertices[topology.edges[e][0]];
    const Point& b = domain.vertices[topology.edges[e][1]];
    for (std::vector<std::pair<double, double>> open = open_parts(a, b, r_e, placed); !open.empty();
         open = open_parts(a, b, r_e, placed)) {
      double total = 0;
      for (const auto& [lo, hi] : open) total += hi - lo;
      if (total * (b - a).norm() < 1e-9 * r_e) break;
      double pick = random.unit() * total;
      bool added = false;
      for (const auto& [lo, hi] : open) {
        if (pick <= hi - lo) {
          added = add(a + (lo + pick) * (b - a), inward_at_edge[e]);
          break;
        }
        pick -= hi - lo;
      }
      if (!added) break;  // the edge's way in leaves the material: an edge not worth protecting
    }
  }
  return seeds;
}

}  // namespace vorocrust::clipping
