#include "check_balls/strata.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <unordered_map>

#include "vorocrust/error.hpp"

namespace vorocrust::checker {
namespace {

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), Index{0}); }
  Index find(Index i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void join(Index i, Index j) {
    i = find(i), j = find(j);
    if (i != j) parent_[std::max(i, j)] = std::min(i, j);  // the lowest index names the set
  }

 private:
  std::vector<Index> parent_;
};

void sort_unique(std::vector<Index>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

Index other_end(const SurfaceEdge& e, Index v) { return e.a == v ? e.b : e.a; }

void build_topology(const SurfaceMesh& mesh, Strata& s) {
  const std::size_t nf = mesh.num_faces();
  s.face_normal.resize(nf);
  s.face_edges.resize(nf);
  s.vertex_edges.assign(mesh.num_vertices(), {});
  s.vertex_faces.assign(mesh.num_vertices(), {});
  std::unordered_map<std::uint64_t, Index> edge_of;
  for (std::size_t f = 0; f < nf; ++f) {
    const Triangle& t = mesh.triangles[f];
    const Point n = (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    const double length = n.norm();
    s.face_normal[f] = length > 0 ? Point(n / length) : Point::Zero();
    for (int k = 0; k < 3; ++k) {
      Index u = t[k], v = t[(k + 1) % 3];
      if (u == v) {
        s.face_edges[f][k] = kNone;
        continue;
      }
      if (u > v) std::swap(u, v);
      const std::uint64_t key = (std::uint64_t{u} << 32) | v;
      auto [it, inserted] = edge_of.try_emplace(key, static_cast<Index>(s.edges.size()));
      if (inserted) {
        s.edges.push_back({u, v, {}});
        s.vertex_edges[u].push_back(it->second);
        s.vertex_edges[v].push_back(it->second);
      }
      s.edges[it->second].faces.push_back(static_cast<Index>(f));
      s.face_edges[f][k] = it->second;
    }
    for (int k = 0; k < 3; ++k) s.vertex_faces[t[k]].push_back(static_cast<Index>(f));
  }
  for (auto& faces : s.vertex_faces) sort_unique(faces);
}

void find_sharp_edges(Strata& s, double theta) {
  s.sharp.resize(s.edges.size());
  for (std::size_t e = 0; e < s.edges.size(); ++e) {
    const auto& faces = s.edges[e].faces;
    s.sharp[e] = faces.size() != 2 || angle_between(s.face_normal[faces[0]], s.face_normal[faces[1]]) > theta;
  }
}

bool is_corner(const SurfaceMesh& mesh, const Strata& s, Index v, double theta) {
  std::vector<Index> sharp_edges;
  for (Index e : s.vertex_edges[v]) {
    if (s.sharp[e]) sharp_edges.push_back(e);
  }
  if (sharp_edges.size() == 1 || sharp_edges.size() > 2) return true;
  if (sharp_edges.size() == 2) {
    const Point& p = mesh.vertices[v];
    const Point& a = mesh.vertices[other_end(s.edges[sharp_edges[0]], v)];
    const Point& b = mesh.vertices[other_end(s.edges[sharp_edges[1]], v)];
    if (angle_between(a - p, p - b) > theta) return true;
  }
  // Sectors: the faces around v joined through its non-sharp edges. A sector whose faces turn by
  // theta or more has no single tangent plane at v.
  const auto& faces = s.vertex_faces[v];
  DisjointSets sectors(faces.size());
  auto local = [&](Index f) {
    return static_cast<Index>(std::lower_bound(faces.begin(), faces.end(), f) - faces.begin());
  };
  for (Index e : s.vertex_edges[v]) {
    if (!s.sharp[e]) sectors.join(local(s.edges[e].faces[0]), local(s.edges[e].faces[1]));
  }
  for (std::size_t i = 0; i < faces.size(); ++i) {
    for (std::size_t j = i + 1; j < faces.size(); ++j) {
      if (sectors.find(static_cast<Index>(i)) != sectors.find(static_cast<Index>(j))) continue;
      const Point &ni = s.face_normal[faces[i]], &nj = s.face_normal[faces[j]];
      if (ni.isZero() || nj.isZero()) continue;
      if (angle_between(ni, nj) >= theta) return true;
    }
  }
  return false;
}

void find_corners(const SurfaceMesh& mesh, Strata& s, double theta) {
  s.vertex_corner.assign(mesh.num_vertices(), kNone);
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    if (s.vertex_faces[v].empty()) continue;  // not on the surface
    if (is_corner(mesh, s, v, theta)) {
      s.vertex_corner[v] = static_cast<Index>(s.corner_vertex.size());
      s.corner_vertex.push_back(v);
    }
  }
}

// Walks one crease from `start` along `first`, until a corner or back to the first edge.
void walk_crease(const SurfaceMesh& mesh, Strata& s, Index crease, Index start, Index first) {
  Index v = start, e = first;
  while (true) {
    const Index w = other_end(s.edges[e], v);
    const Point d = mesh.vertices[w] - mesh.vertices[v];
    const double length = d.norm();
    s.edge_direction[e] = length > 0 ? Point(d / length) : Point::Zero();
    s.edge_crease[e] = crease;
    s.crease_edges[crease].push_back(e);
    if (s.vertex_corner[w] != kNone) {
      s.crease_corners[crease].push_back(s.vertex_corner[w]);
      return;
    }
    Index next = kNone;
    for (Index f : s.vertex_edges[w]) {
      if (s.sharp[f] && f != e) next = f;
    }
    if (next == kNone || s.edge_crease[next] != kNone) return;  // a cycle closed
    v = w, e = next;
  }
}

void find_creases(const SurfaceMesh& mesh, Strata& s) {
  const std::size_t ne = s.edges.size();
  DisjointSets chains(ne);
  s.vertex_crease.assign(mesh.num_vertices(), kNone);
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    if (s.vertex_corner[v] != kNone) continue;
    Index previous = kNone;
    for (Index e : s.vertex_edges[v]) {
      if (!s.sharp[e]) continue;
      if (previous != kNone) chains.join(previous, e);  // a non-corner vertex has 0 or 2 sharp edges
      previous = e;
    }
  }
  // Group sharp edges by chain, in order of the chain's lowest edge.
  std::vector<std::vector<Index>> members(ne);
  std::vector<Index> order;
  for (Index e = 0; e < ne; ++e) {
    if (!s.sharp[e]) continue;
    const Index root = chains.find(e);
    if (members[root].empty()) order.push_back(root);
    members[root].push_back(e);
  }
  s.edge_crease.assign(ne, kNone);
  s.edge_direction.assign(ne, Point::Zero());
  for (Index root : order) {
    const Index crease = static_cast<Index>(s.crease_edges.size());
    s.crease_edges.emplace_back();
    s.crease_corners.emplace_back();
    Index start = kNone, first = kNone;
    for (Index e : members[root]) {
      for (Index v : {s.edges[e].a, s.edges[e].b}) {
        if (start == kNone && s.vertex_corner[v] != kNone) start = v, first = e;
      }
    }
    if (start == kNone) start = s.edges[members[root][0]].a, first = members[root][0];
    else s.crease_corners[crease].push_back(s.vertex_corner[start]);
    walk_crease(mesh, s, crease, start, first);
    if (s.crease_edges[crease].size() != members[root].size()) {
      throw Error(Error::Kind::Internal, "check-balls: crease " + std::to_string(crease) + " is not a simple chain");
    }
    sort_unique(s.crease_corners[crease]);
  }
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    if (s.vertex_corner[v] != kNone) continue;
    for (Index e : s.vertex_edges[v]) {
      if (s.sharp[e]) s.vertex_crease[v] = s.edge_crease[e];
    }
  }
}

void find_patches(const SurfaceMesh& mesh, Strata& s) {
  const std::size_t nf = mesh.num_faces();
  DisjointSets patches(nf);
  for (std::size_t e = 0; e < s.edges.size(); ++e) {
    if (!s.sharp[e]) patches.join(s.edges[e].faces[0], s.edges[e].faces[1]);
  }
  s.face_patch.assign(nf, kNone);
  std::vector<Index> patch_of_root(nf, kNone);
  for (Index f = 0; f < nf; ++f) {
    Index& p = patch_of_root[patches.find(f)];
    if (p == kNone) p = static_cast<Index>(s.num_patches++);
    s.face_patch[f] = p;
  }
  s.patch_creases.assign(s.num_patches, {});
  s.patch_corners.assign(s.num_patches, {});
  for (Index f = 0; f < nf; ++f) {
    const Index p = s.face_patch[f];
    for (Index e : s.face_edges[f]) {
      if (e != kNone && s.sharp[e]) s.patch_creases[p].push_back(s.edge_crease[e]);
    }
    for (Index v : mesh.triangles[f]) {
      if (s.vertex_corner[v] != kNone) s.patch_corners[p].push_back(s.vertex_corner[v]);
    }
  }
  for (auto& list : s.patch_creases) sort_unique(list);
  for (auto& list : s.patch_corners) sort_unique(list);
}

}  // namespace

double angle_between(const Point& u, const Point& v) {
  // atan2 keeps full precision near 0 and pi, where acos of a dot product does not.
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

bool Strata::incident(StratumRef higher, StratumRef lower) const {
  if (dimension(higher.type) <= dimension(lower.type) || higher.index == kNone || lower.index == kNone) return false;
  const std::vector<Index>* list = nullptr;
  if (higher.type == StratumType::Crease) {
    list = &crease_corners[higher.index];
  } else if (lower.type == StratumType::Crease) {
    list = &patch_creases[higher.index];
  } else {
    list = &patch_corners[higher.index];
  }
  return std::binary_search(list->begin(), list->end(), lower.index);
}

Strata find_strata(const SurfaceMesh& mesh, double sharp_angle_radians) {
  Strata s;
  build_topology(mesh, s);
  find_sharp_edges(s, sharp_angle_radians);
  find_corners(mesh, s, sharp_angle_radians);
  find_creases(mesh, s);
  find_patches(mesh, s);
  return s;
}

}  // namespace vorocrust::checker
