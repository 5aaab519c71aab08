#include "io/unfold_faces.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/edge_topology.hpp"
#include "geometry/box_tree.hpp"
#include "geometry/triangle_intersection.hpp"

namespace vorocrust::io {

namespace {

Point face_normal(const SurfaceMesh& mesh, Index f) {
  const Triangle& t = mesh.triangles[f];
  const Point n = (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
  const double length = n.norm();
  return length > 0 ? Point(n / length) : Point(Point::Zero());
}

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
  const auto folds_near = [&](Index v) {
    return std::any_of(faces_at[v].begin(), faces_at[v].end(), [&](Index g) {
      for (Index w : mesh.triangles[g]) {
        for (Index h : faces_at[w]) {
          if (bad(mesh, topology, h)) return true;
        }
      }
      return false;
    });
  };
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
      for (Index v : mesh.triangles[f]) {
        if (pinned[v] || ring[v].empty() || !folds_near(v)) continue;
        Point centroid = Point::Zero();
        for (Index w : ring[v]) centroid += mesh.vertices[w];
        centroid /= static_cast<double>(ring[v].size());
        const Point before = mesh.vertices[v];
        const std::size_t folds_before = count_folds_near(v);
        const std::size_t crossings_before = crossings.count(faces_at[v]);
        mesh.vertices[v] = centroid;
        // A move must not fold more than it unfolds, nor push a face through another sheet
        // (the fold may sit where two sheets nearly touch).
        if (count_folds_near(v) > folds_before || crossings.count(faces_at[v]) > crossings_before) {
          mesh.vertices[v] = before;
        } else {
          moved[v] = true;
          crossings.moved(faces_at[v]);
        }
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
