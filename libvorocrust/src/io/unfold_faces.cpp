#include "io/unfold_faces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/edge_topology.hpp"
#include "core/surface_measures.hpp"
#include "geometry/box_tree.hpp"
#include "geometry/triangle_intersection.hpp"

namespace vorocrust::io {

namespace {

// How many of face f's manifold edges bend by more than the angle whose cosine is `cos_bend`,
// and how many manifold edges it has.
std::pair<int, int> bent_edges(const SurfaceMesh& mesh, const EdgeTopology& topology, Index f, double cos_bend) {
  const Point n = face_normal(mesh, f);
  int bent = 0, manifold = 0;
  if (n.isZero()) return {0, 0};
  for (Index e : topology.face_edges[f]) {
    if (topology.valence(e) != 2) continue;
    const auto faces = topology.faces_of(e);
    const Index g = faces[0] == f ? faces[1] : faces[0];
    // Normals of consistently oriented neighbours: across a fold they point nearly opposite.
    bent += n.dot(face_normal(mesh, g)) < cos_bend;
    ++manifold;
  }
  return {bent, manifold};
}

bool is_folded(const SurfaceMesh& mesh, const EdgeTopology& topology, Index f) {
  const auto [bent, manifold] = bent_edges(mesh, topology, f, std::cos(kFoldDegrees * std::numbers::pi / 180));
  return manifold >= 2 && bent == manifold;
}

}  // namespace

std::vector<Index> folded_faces(const SurfaceMesh& mesh) {
  const EdgeTopology topology = build_edge_topology(mesh);
  std::vector<Index> out;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (is_folded(mesh, topology, f)) out.push_back(f);
  }
  return out;
}

namespace {

geometry::Box box_of(const SurfaceMesh& mesh, Index f) {
  geometry::Box box;
  for (Index v : mesh.triangles[f]) box.include(mesh.vertices[v]);
  return box;
}

// Which faces a face crosses now, for judging a move: a tree over the faces' boxes before any
// move, and the faces of the vertices moved since, whose boxes the tree no longer knows.
class Crossings {
 public:
  explicit Crossings(const SurfaceMesh& mesh) : mesh_(mesh), tree_(boxes(mesh), items(mesh)) {}

  void moved(const std::vector<Index>& faces) { stale_.insert(stale_.end(), faces.begin(), faces.end()); }

  // Pairs (g, h), g among `faces`, that meet other than where they share corners by index.
  std::size_t count(const std::vector<Index>& faces) const {
    std::size_t n = 0;
    for (Index g : faces) {
      const geometry::TriangleCorners t = geometry::corners_of(mesh_, g);
      if (geometry::is_degenerate(t)) continue;
      std::vector<Index> near;
      tree_.for_each_overlap(box_of(mesh_, g), [&](std::uint32_t h) { near.push_back(h); });
      near.insert(near.end(), stale_.begin(), stale_.end());
      std::sort(near.begin(), near.end());
      near.erase(std::unique(near.begin(), near.end()), near.end());
      for (Index h : near) {
        if (h == g) continue;
        const geometry::SharedCorners shared = geometry::shared_corners(mesh_.triangles[g], mesh_.triangles[h]);
        n += geometry::improperly_intersect(t, geometry::corners_of(mesh_, h), shared);
      }
    }
    return n;
  }

 private:
  static std::vector<geometry::Box> boxes(const SurfaceMesh& mesh) {
    std::vector<geometry::Box> out(mesh.num_faces());
    for (Index f = 0; f < mesh.num_faces(); ++f) out[f] = box_of(mesh, f);
    return out;
  }
  static std::vector<std::uint32_t> items(const SurfaceMesh& mesh) {
    std::vector<std::uint32_t> out(mesh.num_faces());
    for (Index f = 0; f < mesh.num_faces(); ++f) out[f] = f;
    return out;
  }

  const SurfaceMesh& mesh_;
  geometry::BoxTree tree_;
  std::vector<Index> stale_;
};

// The cosine of the largest bend across the edges of `faces` (a vertex's faces, so every edge
// whose bend a move of that vertex changes): the smallest dot of neighbouring normals.
double cos_largest_bend(const SurfaceMesh& mesh, const EdgeTopology& topology, const std::vector<Index>& faces) {
  double lowest = 1;
  for (Index f : faces) {
    const Point n = face_normal(mesh, f);
    for (Index e : topology.face_edges[f]) {
      if (topology.valence(e) != 2) continue;
      const auto across = topology.faces_of(e);
      lowest = std::min(lowest, n.dot(face_normal(mesh, across[0] == f ? across[1] : across[0])));
    }
  }
  return lowest;
}

// How far the flattest of `faces` is from a segment: twice its area over its longest edge squared
// (its height over its longest edge; 0.87 for an equilateral triangle).
double least_fullness(const SurfaceMesh& mesh, const std::vector<Index>& faces) {
  double least = std::numeric_limits<double>::infinity();
  for (Index f : faces) {
    const Triangle& t = mesh.triangles[f];
    const Point &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    least = std::min(least, longest > 0 ? (b - a).cross(c - a).norm() / longest : 0.0);
  }
  return least;
}

// A compass search over the axes from `start` for where vertex v unbends its faces most: each
// step taken lowers the largest bend about v and flattens none of its faces below the flattest
// of them before the search (or kLeastFullness): a face squashed onto a segment has a normal that
// any bend fits, so the search would end there (igl_camelhead: vertex 901 put 3.7e-6 from the
// line of its face's other corners, 2.8e-3 apart, a corner whose ball was 1.8e-6 across). The
// step halves from a quarter of `scale` down to a thousandth of it. Returns the place and the
// cosine of the largest bend there.
constexpr double kLeastFullness = 0.05;

std::pair<Point, double> compass_search(SurfaceMesh& mesh, const EdgeTopology& topology, Index v,
                                        const std::vector<Index>& faces, const Point& start, double scale) {
  const Point before = mesh.vertices[v];
  const double fullness_floor = std::min(kLeastFullness, least_fullness(mesh, faces));
  // Below any cosine: a place that squashes a face is never taken.
  const auto score = [&] {
    return least_fullness(mesh, faces) >= fullness_floor ? cos_largest_bend(mesh, topology, faces) : -2.0;
  };
  mesh.vertices[v] = start;
  double best = score();
  for (double step = scale / 4; step > scale / 1000; step /= 2) {
    for (bool improved = true; improved;) {
      improved = false;
      for (int axis = 0; axis < 3; ++axis) {
        for (double sign : {1.0, -1.0}) {
          const Point here = mesh.vertices[v];
          mesh.vertices[v][axis] += sign * step;
          const double c = score();
          if (c > best) {
            best = c;
            improved = true;
          } else {
            mesh.vertices[v] = here;
          }
        }
      }
    }
  }
  const Point found = mesh.vertices[v];
  mesh.vertices[v] = before;
  return {found, best};
}

// Where vertex v should go to unbend its faces most, searched from where it is and from the
// centroid of its ring. The centroid alone can leave a fold nearly as sharp as the one it undid
// where the ring is nearly collinear (igl_camelhead: 147 degrees left of 169).
std::pair<Point, double> unbent_position(SurfaceMesh& mesh, const EdgeTopology& topology, Index v,
                                         const std::vector<Index>& ring, const std::vector<Index>& faces) {
  Point centroid = Point::Zero();
  double mean_edge = 0;
  for (Index w : ring) {
    centroid += mesh.vertices[w];
    mean_edge += (mesh.vertices[w] - mesh.vertices[v]).norm();
  }
  centroid /= static_cast<double>(ring.size());
  mean_edge /= static_cast<double>(ring.size());
  const auto from_centroid = compass_search(mesh, topology, v, faces, centroid, mean_edge);
  const auto from_here = compass_search(mesh, topology, v, faces, mesh.vertices[v], mean_edge);
  return from_here.second >= from_centroid.second ? from_here : from_centroid;
}

// Turns of a fold's corners, and the least gain in the cosine of the largest bend a move must make
// (a twentieth of a degree about 60 degrees), so that the turns end.
constexpr int kUnbendSweeps = 6;
constexpr double kLeastGain = 1e-3;

template <class Bad>
Unfolding relax_faces(SurfaceMesh& mesh, const std::vector<bool>& fixed, Bad&& bad) {
  Unfolding result;
  const EdgeTopology topology = build_edge_topology(mesh);
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (bad(mesh, topology, f)) result.folded.push_back(f);
  }
  if (result.folded.empty()) return result;
  // Neighbours and faces of each vertex, and the vertices that may not move.
  std::vector<std::vector<Index>> ring(mesh.num_vertices()), faces_at(mesh.num_vertices());
  std::vector<bool> pinned(mesh.num_vertices(), false);
  for (std::size_t e = 0; e < topology.num_edges(); ++e) {
    const auto [a, b] = topology.edges[e];
    ring[a].push_back(b);
    ring[b].push_back(a);
    if (topology.valence(e) != 2) pinned[a] = pinned[b] = true;
  }
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    for (Index v : mesh.triangles[f]) faces_at[v].push_back(f);
  }
  for (std::size_t v = 0; v < fixed.size() && v < pinned.size(); ++v) pinned[v] = pinned[v] || fixed[v];
  const auto count_folds_near = [&](Index v) {
    std::size_t n = 0;
    for (Index g : faces_at[v]) {
      for (Index w : mesh.triangles[g]) {
        for (Index h : faces_at[w]) n += bad(mesh, topology, h);
      }
    }
    return n;
  };
  Crossings crossings(mesh);
  std::vector<Index> folded = result.folded;
  std::vector<Point> original = mesh.vertices;
  std::vector<bool> moved(mesh.num_vertices(), false);
  for (int round = 0; round < kUnfoldRounds && !folded.empty(); ++round) {
    for (Index f : folded) {
      // The fold's corners take turns, each to where its faces bend least, until no turn gains:
      // one corner alone can leave its neighbours' edges bent past 100 degrees (igl_camelhead's
      // crumple at vertex 901: 124; all three in turn, 66, as bent as the scan is elsewhere).
      for (int sweep = 0; sweep < kUnbendSweeps; ++sweep) {
        bool gained = false;
        for (Index v : mesh.triangles[f]) {
          if (pinned[v] || ring[v].empty()) continue;
          const double cos_before = cos_largest_bend(mesh, topology, faces_at[v]);
          const auto [target, cos_after] = unbent_position(mesh, topology, v, ring[v], faces_at[v]);
          if (cos_after < cos_before + kLeastGain) continue;
          const Point before = mesh.vertices[v];
          const std::size_t folds_before = count_folds_near(v);
          const std::size_t crossings_before = crossings.count(faces_at[v]);
          mesh.vertices[v] = target;
          // A move must not fold more than it unfolds, nor push a face through another sheet
          // (the fold may sit where two sheets nearly touch).
          if (count_folds_near(v) > folds_before || crossings.count(faces_at[v]) > crossings_before) {
            mesh.vertices[v] = before;
          } else {
            moved[v] = true;
            gained = true;
            crossings.moved(faces_at[v]);
          }
        }
        if (!gained) break;
      }
    }
    std::vector<Index> still;
    for (Index f = 0; f < mesh.num_faces(); ++f) {
      if (bad(mesh, topology, f)) still.push_back(f);
    }
    folded = std::move(still);
  }
  result.remaining = folded;
  for (std::size_t v = 0; v < moved.size(); ++v) {
    if (!moved[v]) continue;
    ++result.moved_vertices;
    result.largest_move = std::max(result.largest_move, (mesh.vertices[v] - original[v]).norm());
  }
  return result;
}

}  // namespace

Unfolding unfold_faces(SurfaceMesh& mesh, const std::vector<bool>& fixed) {
  return relax_faces(mesh, fixed, is_folded);
}

Unfolding flatten_folds(SurfaceMesh& mesh, double max_bend, const std::vector<bool>& fixed) {
  const double cos_bend = std::cos(max_bend);
  return relax_faces(mesh, fixed, [cos_bend](const SurfaceMesh& m, const EdgeTopology& t, Index f) {
    return bent_edges(m, t, f, cos_bend).first > 0;
  });
}

}  // namespace vorocrust::io
