// Adaptive Loop subdivision of the surface patches (paper section 2.2); see smooth_patches.hpp.
#include "features/smooth_patches.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <numeric>
#include <unordered_set>
#include <utility>

#include "core/edge_topology.hpp"
#include "core/surface_measures.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust {

namespace {

constexpr std::int32_t kNoPair = -1;
constexpr Index kNoPoint = static_cast<Index>(-1);

std::uint64_t edge_key(Index a, Index b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t{a} << 32) | b;
}

// One green bisection still present in the mesh: the parent (a, b, c), rotated so the bisected
// edge is a-b, split at `midpoint` m into the halves (a, m, c) and (m, b, c), in that vertex order.
// Keeping the parent lets a later round merge the halves back instead of splitting them again.
struct GreenPair {
  Triangle parent;
  Index midpoint;
  std::array<Index, 2> halves;  // the two faces in the current mesh
};

// The mesh between rounds.
struct Refinement {
  SurfaceMesh mesh;
  std::vector<std::int32_t> face_pair;      // per face: its green pair, or kNoPair
  std::vector<GreenPair> pairs;
  std::unordered_set<std::uint64_t> sharp;  // sharp edges by vertex pair
  std::vector<bool> fixed;                  // per vertex: never moves
  double cos_kink = -1;                     // no non-sharp edge may end a round bent more than this (cosine)
};

// Cosine of the bend across manifold edge e: the angle between its two faces' normals. Neighbours
// of opposite orientation (a non-orientable patch) are compared as lines.
double bend_cos(const std::vector<Triangle>& triangles, const std::vector<Point>& normals, const EdgeTopology& topo,
                std::size_t e) {
  const auto faces = topo.faces_of(e);
  const double c = normals[faces[0]].dot(normals[faces[1]]);
  const auto [a, b] = topo.edges[e];
  return edge_direction(triangles[faces[0]], a, b) == edge_direction(triangles[faces[1]], a, b) ? -c : c;
}

// Loop's original weight for a vertex of valence n (Loop 1987); 1/16 for the regular n = 6.
double loop_beta(std::size_t n) {
  const double c = 3.0 / 8.0 + 0.25 * std::cos(2 * std::numbers::pi / static_cast<double>(n));
  return (5.0 / 8.0 - c * c) / static_cast<double>(n);
}

int slot_of(const EdgeTopology& topo, Index face, Index edge) {
  const auto& fe = topo.face_edges[face];
  return fe[0] == edge ? 0 : fe[1] == edge ? 1 : 2;
}

std::size_t corner_of(const SurfaceMesh& mesh, Index f, Index v) {
  const Triangle& t = mesh.triangles[f];
  return 3 * std::size_t{f} + (t[0] == v ? 0 : t[1] == v ? 1 : 2);
}

std::size_t find_root(std::vector<std::size_t>& parent, std::size_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// Vertices where several fans of faces meet (the surface is pinched there): Loop's vertex rule
// assumes one fan, and moving such a vertex would blend unrelated sheets.
std::vector<bool> pinched_vertices(const SurfaceMesh& mesh, const EdgeTopology& topo) {
  // Union the corners (face, slot) of the faces on both sides of each manifold edge, per end.
  // Filled one by one: a zero-filled vector made here trips GCC 12's -Warray-bounds (a false
  // positive about the memset of an empty mesh's vector).
  std::vector<std::size_t> parent;
  parent.reserve(3 * mesh.num_faces());
  for (std::size_t c = 0; c < 3 * mesh.num_faces(); ++c) parent.push_back(c);
  for (std::size_t e = 0; e < topo.num_edges(); ++e) {
    if (topo.valence(e) != 2) continue;
    const auto faces = topo.faces_of(e);
    for (Index v : topo.edges[e]) {
      parent[find_root(parent, corner_of(mesh, faces[0], v))] = find_root(parent, corner_of(mesh, faces[1], v));
    }
  }
  std::vector<std::size_t> fan(mesh.num_vertices(), SIZE_MAX);
  std::vector<bool> pinched(mesh.num_vertices(), false);
  for (std::size_t c = 0; c < parent.size(); ++c) {
    const Index v = mesh.triangles[c / 3][c % 3];
    const std::size_t root = find_root(parent, c);
    if (fan[v] == SIZE_MAX) fan[v] = root;
    else if (fan[v] != root) pinched[v] = true;
  }
  return pinched;
}

// The edge rule's view of the vertices that may not move. Around a fixed vertex v the faces
// joined across non-sharp edges form sectors. Loop's edge rule assumes v moves too; held still,
// the ring of edge points around it contracts at a different rate than the sharp edges (which
// halve), and the surface grows a ridge or a spike at v over the rounds.
// - In a sector bounded by sharp edges (creases, boundaries) an edge v-r gets
//   (3/4 - gamma) v + gamma r + 1/8 (c + d), gamma = 1/2 - 1/4 cos(alpha / k) for a sector of k
//   faces spanning the angle alpha at v: the crease/corner rule of Biermann, Levin and Zorin
//   (2000), with the sector's own angle. It is Loop's 3/8, 3/8 on a flat regular crease (k = 3,
//   alpha = pi) and makes the ring contract by exactly 1/2 in the sector.
// - A fixed vertex with at most one sharp edge (an isolated cone corner, a crease ending inside a
//   patch, a pinch) has nothing bounding its fan, and no such rule keeps its ring from rising
//   faster than it shrinks; its edges are split at their midpoints, so its fan stays the input's
//   cone at every level.
class FixedEnds {
 public:
  FixedEnds(const SurfaceMesh& mesh, const EdgeTopology& topo, const std::vector<bool>& sharp,
            const std::vector<bool>& fixed)
      : mesh_(mesh), fixed_(fixed), root_(3 * mesh.num_faces()), sharp_count_(mesh.num_vertices(), 0) {
    std::iota(root_.begin(), root_.end(), std::size_t{0});
    for (std::size_t e = 0; e < topo.num_edges(); ++e) {
      const auto [a, b] = topo.edges[e];
      if (sharp[e]) {
        ++sharp_count_[a];
        ++sharp_count_[b];
        continue;
      }
      const auto faces = topo.faces_of(e);
      for (Index v : {a, b}) {
        if (fixed[v]) {
          root_[find_root(root_, corner_of(mesh, faces[0], v))] = find_root(root_, corner_of(mesh, faces[1], v));
        }
      }
    }
    angle_.assign(root_.size(), 0.0);
    faces_.assign(root_.size(), 0);
    for (std::size_t c = 0; c < root_.size(); ++c) {
      const Triangle& t = mesh.triangles[c / 3];
      const Index v = t[c % 3];
      if (!fixed[v]) continue;
      const Point u = mesh.vertices[t[(c + 1) % 3]] - mesh.vertices[v];
      const Point w = mesh.vertices[t[(c + 2) % 3]] - mesh.vertices[v];
      const std::size_t root = find_root(root_, c);
      angle_[root] += std::atan2(u.cross(w).norm(), u.dot(w));
      ++faces_[root];
    }
  }

  bool fixed(Index v) const { return fixed_[v]; }
  bool cone(Index v) const { return fixed_[v] && sharp_count_[v] <= 1; }
  // gamma of the sector of fixed vertex v that holds face f.
  double gamma(Index f, Index v) {
    const std::size_t root = find_root(root_, corner_of(mesh_, f, v));
    return 0.5 - 0.25 * std::cos(angle_[root] / faces_[root]);
  }

 private:
  const SurfaceMesh& mesh_;
  const std::vector<bool>& fixed_;
  std::vector<std::size_t> root_;  // union-find over corners 3 f + slot
  std::vector<double> angle_;      // at a sector's root: the sum of its faces' angles at the vertex
  std::vector<int> faces_;         // at a sector's root: its number of faces
  std::vector<int> sharp_count_;   // per vertex
};

enum class Split : std::uint8_t { None, Green, Red };

// How a round places its points and which faces it splits.
enum class Rule : std::uint8_t {
  Loop,      // Loop's rules, on faces whose patch still bends
  Midpoint,  // edge midpoints and nothing moved, on faces about vertices Loop would move too far
};

// The sum of each vertex's neighbours over the mesh's edges, and how many there are.
struct Rings {
  std::vector<Point> sum;
  std::vector<std::size_t> valence;
};

Rings rings_of(const std::vector<Point>& p, const EdgeTopology& topo) {
  Rings rings{std::vector<Point>(p.size(), Point::Zero()), std::vector<std::size_t>(p.size(), 0)};
  for (const auto& [a, b] : topo.edges) {
    rings.sum[a] += p[b], ++rings.valence[a];
    rings.sum[b] += p[a], ++rings.valence[b];
  }
  return rings;
}

// The faces a Loop round splits: those with a non-sharp edge bent by more than
// pi - flat_dihedral, not flat yet.
std::vector<bool> bent_faces(const Refinement& r, const EdgeTopology& topo, const std::vector<bool>& sharp,
                             const SmoothingOptions& options) {
  const SurfaceMesh& mesh = r.mesh;
  std::vector<Point> normal(mesh.num_faces());
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) normal[f] = unit_normal(mesh.vertices, mesh.triangles[f]);
  const double cos_bend = std::cos(std::numbers::pi - options.flat_dihedral_degrees * std::numbers::pi / 180);
  std::vector<bool> marked(mesh.num_faces(), false);
  for (std::size_t e = 0; e < topo.num_edges(); ++e) {
    if (sharp[e]) continue;
    const auto faces = topo.faces_of(e);
    // A zero-area face has no normal to compare; it is split only when its neighbours force it.
    if (normal[faces[0]].isZero() || normal[faces[1]].isZero()) continue;
    if (bend_cos(mesh.triangles, normal, topo, e) < cos_bend) marked[faces[0]] = marked[faces[1]] = true;
  }
  return marked;
}

// Per vertex, how far Loop's rules carried to their limit would move it across the surface (0
// for the vertices that never move). Loop's limit point of a vertex v of valence n is
// v + n chi (mean of its neighbours - v), chi = 1 / (n + 3 / (8 beta)) (Loop 1987); its component
// along v's normal is how far the smooth surface leaves the input at v, the tangential part only
// sliding along it. Splitting every edge at v halves its neighbours' offset from it, and so this
// move; the new midpoints are judged in the next round.
std::vector<double> limit_offsets(const Refinement& r, const EdgeTopology& topo) {
  const SurfaceMesh& mesh = r.mesh;
  const std::vector<Point>& p = mesh.vertices;
  const Rings rings = rings_of(p, topo);
  // Area-weighted over the faces as oriented (validation makes them agree; a fold bent past 90
  // degrees still adds up the right way round). On a non-orientable patch they partly cancel,
  // and the move is underestimated there.
  std::vector<Point> normal(p.size(), Point::Zero());
  for (const Triangle& t : mesh.triangles) {
    const Point n = (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]);
    for (Index v : t) normal[v] += n;
  }
  std::vector<double> offset(p.size(), 0.0);
  for (Index v = 0; v < p.size(); ++v) {
    const std::size_t valence = rings.valence[v];
    if (r.fixed[v] || valence == 0 || normal[v].isZero()) continue;
    const auto n = static_cast<double>(valence);
    const double chi = 1 / (n + 3 / (8 * loop_beta(valence)));
    offset[v] = std::abs((n * chi * (rings.sum[v] / n - p[v])).dot(normal[v].normalized()));
  }
  return offset;
}

// The faces a Midpoint round splits: those with a vertex that Loop's rules would move across the
// surface by more than options.max_deviation, so that where the input's tessellation is coarse
// for how much it bends, the smooth surface comes closer to it.
std::vector<bool> straying_faces(const Refinement& r, const EdgeTopology& topo, const SmoothingOptions& options) {
  const std::vector<double> offset = limit_offsets(r, topo);
  std::vector<bool> marked(r.mesh.num_faces(), false);
  for (std::size_t f = 0; f < marked.size(); ++f) {
    const Triangle& t = r.mesh.triangles[f];
    marked[f] = std::max({offset[t[0]], offset[t[1]], offset[t[2]]}) > options.max_deviation;
  }
  return marked;
}

// The kink guard, after a Loop round. Loop's stencils presume a smooth, even neighbourhood; on
// skinny or folded input faces, or next to vertices held still, they can pull a point across its
// neighbours and fold or spike the surface. Wherever a non-sharp edge ends up bent more than the
// input's worst patch edge (or a face has no area), the vertices of its two faces fall back to
// linear subdivision (midpoints, old vertices in place), which only repeats bends that were
// there. Vertices only ever fall back, so this ends.
void guard_kinks(const Refinement& r, const std::vector<Point>& linear, SurfaceMesh& out) {
  const EdgeTopology out_topo = build_edge_topology(out);
  std::vector<Point>& placed = out.vertices;
  std::vector<Point> out_normal(out.num_faces());
  for (std::size_t g = 0; g < out.num_faces(); ++g) out_normal[g] = unit_normal(placed, out.triangles[g]);
  std::vector<bool> guarded(out_topo.num_edges(), false);
  for (std::size_t e = 0; e < out_topo.num_edges(); ++e) {
    guarded[e] = out_topo.valence(e) == 2 && !r.sharp.contains(edge_key(out_topo.edges[e][0], out_topo.edges[e][1]));
  }
  std::vector<std::size_t> face_offset(out.num_vertices() + 1, 0);  // faces around each vertex
  for (const Triangle& t : out.triangles) {
    for (Index v : t) ++face_offset[v + 1];
  }
  std::partial_sum(face_offset.begin(), face_offset.end(), face_offset.begin());
  std::vector<Index> faces_at(face_offset.back());
  {
    std::vector<std::size_t> fill(face_offset.begin(), face_offset.end() - 1);
    for (Index g = 0; g < out.num_faces(); ++g) {
      for (Index v : out.triangles[g]) faces_at[fill[v]++] = g;
    }
  }
  std::vector<Index> dirty(out.num_faces());
  std::iota(dirty.begin(), dirty.end(), Index{0});
  std::vector<bool> queued(out.num_faces(), false);
  while (!dirty.empty()) {
    std::vector<Index> next;
    for (Index g : dirty) {
      for (Index e : out_topo.face_edges[g]) {
        if (!guarded[e]) continue;
        const auto faces = out_topo.faces_of(e);
        const bool flat_enough = !out_normal[faces[0]].isZero() && !out_normal[faces[1]].isZero() &&
                                 bend_cos(out.triangles, out_normal, out_topo, e) >= r.cos_kink;
        if (flat_enough) continue;
        for (Index h : faces) {
          for (Index v : out.triangles[h]) {
            if (placed[v] == linear[v]) continue;
            placed[v] = linear[v];
            for (std::size_t i = face_offset[v]; i < face_offset[v + 1]; ++i) {
              const Index k = faces_at[i];
              out_normal[k] = unit_normal(placed, out.triangles[k]);
              if (!queued[k]) queued[k] = true, next.push_back(k);
            }
          }
        }
      }
    }
    for (Index g : next) queued[g] = false;
    dirty = std::move(next);
  }
}

// One round of adaptive subdivision by `rule`. Returns the number of faces of the current mesh
// that were replaced, or 0 when nothing is marked or the round would exceed options.max_faces
// (the mesh is then left as it was).
std::size_t refine_once(Refinement& r, const SmoothingOptions& options, Rule rule) {
  const SurfaceMesh& mesh = r.mesh;
  const EdgeTopology topo = build_edge_topology(mesh);
  const std::size_t num_faces = mesh.num_faces(), num_edges = topo.num_edges();
  const std::vector<Point>& old = mesh.vertices;

  std::vector<bool> sharp(num_edges);
  for (std::size_t e = 0; e < num_edges; ++e) {
    sharp[e] = topo.valence(e) != 2 || r.sharp.contains(edge_key(topo.edges[e][0], topo.edges[e][1]));
  }

  const std::vector<bool> marked =
      rule == Rule::Loop ? bent_faces(r, topo, sharp, options) : straying_faces(r, topo, options);
  if (std::find(marked.begin(), marked.end(), true) == marked.end()) return 0;

  // Red-green closure, to a fixed point: splitting an edge revisits the faces around it.
  std::vector<bool> split_edge(num_edges, false);
  std::vector<Split> split_face(num_faces, Split::None);
  std::vector<bool> upgraded(r.pairs.size(), false);
  std::vector<Index> newly_split;
  const auto split = [&](Index e) {
    if (split_edge[e]) return;
    split_edge[e] = true;
    newly_split.push_back(e);
  };
  const auto make_red = [&](Index f) {
    if (split_face[f] == Split::Red) return;
    split_face[f] = Split::Red;
    for (Index e : topo.face_edges[f]) split(e);
  };
  // A green pair that must change is merged back and its parent split red: its two whole edges
  // split now, the bisected one already is (at the pair's midpoint).
  const auto upgrade = [&](std::int32_t p) {
    if (upgraded[p]) return;
    upgraded[p] = true;
    const GreenPair& pair = r.pairs[p];
    split(topo.face_edges[pair.halves[0]][2]);  // c-a
    split(topo.face_edges[pair.halves[1]][1]);  // b-c
  };
  const auto split_count = [&](Index f) {
    int count = 0;
    for (Index e : topo.face_edges[f]) count += split_edge[e] ? 1 : 0;
    return count;
  };
  for (Index f = 0; f < num_faces; ++f) {
    if (!marked[f]) continue;
    if (r.face_pair[f] != kNoPair) upgrade(r.face_pair[f]);
    else make_red(f);
  }
  while (!newly_split.empty()) {
    const Index e = newly_split.back();
    newly_split.pop_back();
    for (Index f : topo.faces_of(e)) {
      if (r.face_pair[f] != kNoPair) upgrade(r.face_pair[f]);  // a green half is never split itself
      else if (split_count(f) >= 2) make_red(f);
    }
  }

  // Count the result before building it, to honour max_faces.
  std::size_t replaced = 0, result_faces = num_faces;
  for (Index f = 0; f < num_faces; ++f) {
    if (r.face_pair[f] != kNoPair) continue;
    if (split_face[f] == Split::None && split_count(f) == 1) split_face[f] = Split::Green;
    if (split_face[f] == Split::Red) result_faces += 3, ++replaced;
    if (split_face[f] == Split::Green) result_faces += 1, ++replaced;
  }
  for (std::size_t p = 0; p < r.pairs.size(); ++p) {
    if (!upgraded[p]) continue;
    const GreenPair& pair = r.pairs[p];
    // The bisector m-c disappears with the merge; only a red half could split it, and the
    // closure never makes one.
    if (split_edge[topo.face_edges[pair.halves[0]][1]]) {
      throw Error(Error::Kind::Internal, "smooth_patches: the bisector of a green pair was split");
    }
    result_faces += 2, replaced += 2;
    for (Index half : pair.halves) result_faces += split_edge[topo.face_edges[half][0]] ? 1 : 0;
  }
  if (result_faces > options.max_faces) return 0;

  // Edge points, from the positions at the start of the round; `linear` keeps each new vertex's
  // plain midpoint for the kink guard below.
  FixedEnds ends(mesh, topo, sharp, r.fixed);
  std::vector<Index> edge_point(num_edges, kNoPoint);
  std::vector<Point> points = old, linear = old;
  for (Index e = 0; e < num_edges; ++e) {
    if (!split_edge[e]) continue;
    const auto [a, b] = topo.edges[e];
    edge_point[e] = static_cast<Index>(points.size());
    const Point midpoint = 0.5 * (old[a] + old[b]);
    linear.push_back(midpoint);
    // Creases keep their straight edges exactly; cone points keep their cones.
    if (rule == Rule::Midpoint || sharp[e] || ends.cone(a) || ends.cone(b)) {
      points.push_back(midpoint);
      continue;
    }
    Point opposite = Point::Zero();
    for (Index f : topo.faces_of(e)) {
      const int k = slot_of(topo, f, e);
      Index apex = mesh.triangles[f][(k + 2) % 3];
      // A whole parent edge on a green half belongs to the parent's level: use its apex.
      if (const std::int32_t p = r.face_pair[f]; p != kNoPair) {
        const GreenPair& pair = r.pairs[p];
        if (f == pair.halves[0] && k == 2) apex = pair.parent[1];
        if (f == pair.halves[1] && k == 1) apex = pair.parent[0];
      }
      opposite += old[apex];
    }
    double wa = 3.0 / 8.0, wb = 3.0 / 8.0;
    const Index f0 = topo.faces_of(e)[0];
    if (ends.fixed(a) && ends.fixed(b)) {  // the average of the rule seen from either end
      const double ga = ends.gamma(f0, a), gb = ends.gamma(f0, b);
      wa = 3.0 / 8.0 + 0.5 * (gb - ga);
      wb = 3.0 / 8.0 + 0.5 * (ga - gb);
    } else if (ends.fixed(a)) {
      wb = ends.gamma(f0, a);
      wa = 0.75 - wb;
    } else if (ends.fixed(b)) {
      wa = ends.gamma(f0, b);
      wb = 0.75 - wa;
    }
    points.push_back(wa * old[a] + wb * old[b] + 1.0 / 8.0 * opposite);
  }

  // Loop's vertex rule for the free vertices of replaced faces, over the conforming mesh's edges.
  if (rule == Rule::Loop) {
    std::vector<bool> moves(old.size(), false);
    for (Index f = 0; f < num_faces; ++f) {
      const std::int32_t p = r.face_pair[f];
      if (p != kNoPair ? !upgraded[p] : split_face[f] == Split::None) continue;
      for (Index v : mesh.triangles[f]) moves[v] = !r.fixed[v];
    }
    const Rings rings = rings_of(old, topo);
    for (Index v = 0; v < old.size(); ++v) {
      const std::size_t valence = rings.valence[v];
      if (!moves[v] || valence == 0) continue;
      const double beta = loop_beta(valence);
      points[v] = (1 - static_cast<double>(valence) * beta) * old[v] + beta * rings.sum[v];
    }
  }

  // The subdivided mesh. Children are emitted where their parent was, in its vertex order.
  SurfaceMesh out;
  out.groups = mesh.groups;
  out.region_names = mesh.region_names;
  out.vertices = std::move(points);
  out.triangles.reserve(result_faces);
  out.face_group.reserve(result_faces);
  out.face_line.reserve(result_faces);
  out.face_source.reserve(result_faces);
  if (mesh.has_regions()) out.face_regions.reserve(result_faces);
  std::vector<std::int32_t> out_face_pair;
  out_face_pair.reserve(result_faces);
  std::vector<GreenPair> out_pairs;
  const auto emit = [&](const Triangle& t, Index source) {
    out.triangles.push_back(t);
    out.face_group.push_back(mesh.face_group[source]);
    out.face_line.push_back(mesh.face_line[source]);
    out.face_source.push_back(mesh.source_face(source));
    if (mesh.has_regions()) out.face_regions.push_back(mesh.face_regions[source]);
    out_face_pair.push_back(kNoPair);
    return static_cast<Index>(out.triangles.size() - 1);
  };
  // Bisects (a, b, c) on a-b at m.
  const auto emit_green = [&](const Triangle& t, Index m, Index source) {
    const auto p = static_cast<std::int32_t>(out_pairs.size());
    const Index h0 = emit({t[0], m, t[2]}, source), h1 = emit({m, t[1], t[2]}, source);
    out_face_pair[h0] = out_face_pair[h1] = p;
    out_pairs.push_back({t, m, {h0, h1}});
  };
  for (Index f = 0; f < num_faces; ++f) {
    const Triangle& t = mesh.triangles[f];
    const auto& fe = topo.face_edges[f];
    if (const std::int32_t p = r.face_pair[f]; p != kNoPair) {
      const GreenPair& pair = r.pairs[p];
      if (f != pair.halves[0]) continue;  // a pair is emitted once, with its first half
      if (!upgraded[p]) {
        emit_green(pair.parent, pair.midpoint, f);
        continue;
      }
      const auto [a, b, c] = pair.parent;
      const Index m = pair.midpoint;
      const auto& e0 = topo.face_edges[pair.halves[0]];
      const auto& e1 = topo.face_edges[pair.halves[1]];
      const Index m_ca = edge_point[e0[2]], m_bc = edge_point[e1[1]];
      // The corner children along the old green edge may have to be bisected in this round.
      if (split_edge[e0[0]]) emit_green({a, m, m_ca}, edge_point[e0[0]], f);
      else emit({a, m, m_ca}, f);
      if (split_edge[e1[0]]) emit_green({m, b, m_bc}, edge_point[e1[0]], f);
      else emit({m, b, m_bc}, f);
      emit({m_ca, m_bc, c}, f);
      emit({m, m_bc, m_ca}, f);
      continue;
    }
    switch (split_face[f]) {
      case Split::None: emit(t, f); break;
      case Split::Green: {
        const int k = split_edge[fe[0]] ? 0 : split_edge[fe[1]] ? 1 : 2;
        emit_green({t[k], t[(k + 1) % 3], t[(k + 2) % 3]}, edge_point[fe[k]], f);
        break;
      }
      case Split::Red: {
        const Index p0 = edge_point[fe[0]], p1 = edge_point[fe[1]], p2 = edge_point[fe[2]];
        emit({t[0], p0, p2}, f);
        emit({p0, t[1], p1}, f);
        emit({p2, p1, t[2]}, f);
        emit({p0, p1, p2}, f);
        break;
      }
    }
  }

  // Sharp edges split into sharp halves whose midpoint, on the crease, is fixed from now on.
  r.fixed.resize(out.vertices.size(), false);
  for (Index e = 0; e < num_edges; ++e) {
    if (!split_edge[e] || !sharp[e]) continue;
    const auto [a, b] = topo.edges[e];
    const Index m = edge_point[e];
    r.sharp.erase(edge_key(a, b));
    r.sharp.insert(edge_key(a, m));
    r.sharp.insert(edge_key(m, b));
    r.fixed[m] = true;
  }

  if (rule == Rule::Loop) guard_kinks(r, linear, out);

  r.mesh = std::move(out);
  r.face_pair = std::move(out_face_pair);
  r.pairs = std::move(out_pairs);
  return replaced;
}

}  // namespace

SmoothedSurface smooth_patches(const SurfaceMesh& mesh, const Strata& strata, const SmoothingOptions& options) {
  const EdgeTopology& topo = strata.topology;
  if (topo.face_edges.size() != mesh.num_faces() || strata.sharp_edge.size() != topo.num_edges() ||
      strata.vertex_corner.size() != mesh.num_vertices()) {
    throw Error(Error::Kind::Usage, "smooth_patches: the strata were not detected on this mesh");
  }

  Refinement r;
  r.mesh = mesh;
  r.face_pair.assign(mesh.num_faces(), kNoPair);
  r.fixed = pinched_vertices(mesh, topo);
  for (std::size_t e = 0; e < topo.num_edges(); ++e) {
    if (!strata.sharp_edge[e] && topo.valence(e) == 2) continue;
    const auto [a, b] = topo.edges[e];
    r.sharp.insert(edge_key(a, b));
    r.fixed[a] = r.fixed[b] = true;
  }
  for (Index v : strata.corners) r.fixed[v] = true;

  // The kink guard's limit: the worst bend inside a patch of the input, but no less than the
  // flatness the marking aims for.
  std::vector<Point> normal(mesh.num_faces());
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) normal[f] = unit_normal(mesh.vertices, mesh.triangles[f]);
  r.cos_kink = std::cos(std::numbers::pi - options.flat_dihedral_degrees * std::numbers::pi / 180);
  for (std::size_t e = 0; e < topo.num_edges(); ++e) {
    if (r.sharp.contains(edge_key(topo.edges[e][0], topo.edges[e][1]))) continue;
    const auto faces = topo.faces_of(e);
    if (normal[faces[0]].isZero() || normal[faces[1]].isZero()) continue;
    r.cos_kink = std::min(r.cos_kink, bend_cos(mesh.triangles, normal, topo, e));
  }
  r.cos_kink -= 1e-9;  // linear subdivision repeats the worst bend up to rounding

  SmoothedSurface result;
  // First the midpoint splits that keep Loop's surface near the input, only for a smoothing that
  // has rounds of Loop's to follow them.
  const bool bounded = options.max_deviation > 0 && options.max_iterations > 0;
  for (int round = 0; bounded && round < options.max_bounding_rounds; ++round) {
    const std::size_t replaced = refine_once(r, options, Rule::Midpoint);
    if (replaced == 0) break;
    ++result.bounding_rounds;
    result.faces_split += replaced;
  }
  if (bounded) {
    const std::vector<double> offset = limit_offsets(r, build_edge_topology(r.mesh));
    result.largest_limit_offset = offset.empty() ? 0 : *std::max_element(offset.begin(), offset.end());
  }
  for (int round = 0; round < options.max_iterations; ++round) {
    const std::size_t replaced = refine_once(r, options, Rule::Loop);
    if (replaced == 0) break;
    ++result.iterations;
    result.faces_split += replaced;
  }

  result.mesh = std::move(r.mesh);
  result.corners = strata.corners;
  result.sharp_edges.reserve(r.sharp.size());
  for (std::uint64_t key : r.sharp) {
    result.sharp_edges.push_back({static_cast<Index>(key >> 32), static_cast<Index>(key & 0xffffffffu)});
  }
  std::sort(result.sharp_edges.begin(), result.sharp_edges.end());
  return result;
}

Strata strata_after_smoothing(const SmoothedSurface& smoothed) {
  const SurfaceMesh& mesh = smoothed.mesh;
  const EdgeTopology topo = build_edge_topology(mesh);
  // sharp_edges is sorted by (smaller, larger) vertex, like the topology's edges.
  std::vector<bool> sharp(topo.num_edges(), false);
  for (std::size_t e = 0; e < topo.num_edges(); ++e) {
    sharp[e] = std::binary_search(smoothed.sharp_edges.begin(), smoothed.sharp_edges.end(), topo.edges[e]);
  }
  std::vector<bool> corner(mesh.num_vertices(), false);
  for (Index v : smoothed.corners) corner[v] = true;
  return build_strata(mesh, std::move(sharp), std::move(corner));
}

}  // namespace vorocrust
