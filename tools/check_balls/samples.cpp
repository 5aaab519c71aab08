#include "check_balls/samples.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace vorocrust::checker {
namespace {

// SplitMix64: tiny, and unlike the standard distributions it gives the same numbers everywhere.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  double uniform() {  // in [0, 1)
    state_ += 0x9E3779B97F4A7C15ull;
    std::uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
  }

 private:
  std::uint64_t state_;
};

class SampleWriter {
 public:
  explicit SampleWriter(SampleSet& set) : set_(set) {}

  // Adds a sample with the given candidate directions, skipping zero ones; drops it if none is left.
  void add(const Point& position, StratumRef stratum, SampleSource source, Index element,
           std::initializer_list<Point> directions) {
    add_range(position, stratum, source, element, directions.begin(), directions.end());
  }
  template <class It>
  void add_range(const Point& position, StratumRef stratum, SampleSource source, Index element, It begin, It end) {
    Sample s{position, stratum, static_cast<Index>(set_.directions.size()), 0, source, element};
    for (It it = begin; it != end; ++it) {
      if (it->isZero()) continue;
      set_.directions.push_back(*it);
      ++s.direction_count;
    }
    if (stratum.type != StratumType::Corner && s.direction_count == 0) return;
    set_.samples.push_back(s);
    ++count(source);
  }

 private:
  std::size_t& count(SampleSource source) {
    SampleCounts& c = set_.counts;
    switch (source) {
      case SampleSource::Vertex: return c.vertices;
      case SampleSource::EdgeMidpoint: return c.edge_midpoints;
      case SampleSource::FaceCentroid: return c.face_centroids;
      case SampleSource::RandomOnFace: return c.on_faces;
      case SampleSource::RandomOnCrease: return c.on_creases;
    }
    return c.vertices;
  }
  SampleSet& set_;
};

void add_vertex_samples(const SurfaceMesh& mesh, const Strata& s, SampleWriter& out) {
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    if (s.vertex_faces[v].empty()) continue;
    const Point& x = mesh.vertices[v];
    if (s.vertex_corner[v] != kNone) {
      out.add(x, {StratumType::Corner, s.vertex_corner[v]}, SampleSource::Vertex, v, {});
    } else if (s.vertex_crease[v] != kNone) {
      std::vector<Point> directions;
      for (Index e : s.vertex_edges[v]) {
        if (s.sharp[e]) directions.push_back(s.edge_direction[e]);
      }
      out.add_range(x, {StratumType::Crease, s.vertex_crease[v]}, SampleSource::Vertex, v, directions.begin(),
                    directions.end());
    } else {
      // Usually one patch; a vertex where several patches touch without a sharp edge is on each.
      std::vector<Index> patches;
      for (Index f : s.vertex_faces[v]) patches.push_back(s.face_patch[f]);
      std::sort(patches.begin(), patches.end());
      patches.erase(std::unique(patches.begin(), patches.end()), patches.end());
      for (Index p : patches) {
        std::vector<Point> normals;
        for (Index f : s.vertex_faces[v]) {
          if (s.face_patch[f] == p) normals.push_back(s.face_normal[f]);
        }
        out.add_range(x, {StratumType::Patch, p}, SampleSource::Vertex, v, normals.begin(), normals.end());
      }
    }
  }
}

void add_edge_midpoints(const SurfaceMesh& mesh, const Strata& s, SampleWriter& out) {
  for (Index e = 0; e < s.edges.size(); ++e) {
    const SurfaceEdge& edge = s.edges[e];
    const Point x = 0.5 * (mesh.vertices[edge.a] + mesh.vertices[edge.b]);
    if (s.sharp[e]) {
      out.add(x, {StratumType::Crease, s.edge_crease[e]}, SampleSource::EdgeMidpoint, e, {s.edge_direction[e]});
    } else {
      out.add(x, {StratumType::Patch, s.face_patch[edge.faces[0]]}, SampleSource::EdgeMidpoint, e,
              {s.face_normal[edge.faces[0]], s.face_normal[edge.faces[1]]});
    }
  }
}

void add_face_centroids(const SurfaceMesh& mesh, const Strata& s, SampleWriter& out) {
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const Point x = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
    out.add(x, {StratumType::Patch, s.face_patch[f]}, SampleSource::FaceCentroid, f, {s.face_normal[f]});
  }
}

// Index i with probability weight[i] / total; zero weights are never chosen.
Index pick(const std::vector<double>& cumulative, Random& random) {
  const double target = random.uniform() * cumulative.back();
  const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), target);
  return static_cast<Index>(std::min<std::ptrdiff_t>(it - cumulative.begin(), cumulative.size() - 1));
}

void add_random_on_faces(const SurfaceMesh& mesh, const Strata& s, std::size_t n, Random& random, SampleWriter& out) {
  std::vector<double> cumulative(mesh.num_faces());
  double total = 0;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[f];
    total += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).norm();
    cumulative[f] = total;
  }
  if (!(total > 0)) return;
  for (std::size_t i = 0; i < n; ++i) {
    const Index f = pick(cumulative, random);
    const Triangle& t = mesh.triangles[f];
    // Uniform on the triangle: the square root spreads points evenly from the first corner.
    const double r = std::sqrt(random.uniform()), u = random.uniform();
    const Point x = (1 - r) * mesh.vertices[t[0]] + r * (1 - u) * mesh.vertices[t[1]] + r * u * mesh.vertices[t[2]];
    out.add(x, {StratumType::Patch, s.face_patch[f]}, SampleSource::RandomOnFace, f, {s.face_normal[f]});
  }
}

void add_random_on_creases(const SurfaceMesh& mesh, const Strata& s, std::size_t n, Random& random,
                           SampleWriter& out) {
  std::vector<Index> sharp_edges;
  std::vector<double> cumulative;
  double total = 0;
  for (Index e = 0; e < s.edges.size(); ++e) {
    if (!s.sharp[e]) continue;
    total += (mesh.vertices[s.edges[e].b] - mesh.vertices[s.edges[e].a]).norm();
    sharp_edges.push_back(e);
    cumulative.push_back(total);
  }
  if (!(total > 0)) return;
  for (std::size_t i = 0; i < n; ++i) {
    const Index e = sharp_edges[pick(cumulative, random)];
    const double t = random.uniform();
    const Point x = (1 - t) * mesh.vertices[s.edges[e].a] + t * mesh.vertices[s.edges[e].b];
    out.add(x, {StratumType::Crease, s.edge_crease[e]}, SampleSource::RandomOnCrease, e, {s.edge_direction[e]});
  }
}

}  // namespace

const char* to_string(SampleSource source) noexcept {
  switch (source) {
    case SampleSource::Vertex: return "vertex";
    case SampleSource::EdgeMidpoint: return "edge midpoint";
    case SampleSource::FaceCentroid: return "face centroid";
    case SampleSource::RandomOnFace: return "random point on face";
    case SampleSource::RandomOnCrease: return "random point on sharp edge";
  }
  return "sample";
}

SampleSet make_samples(const SurfaceMesh& mesh, const Strata& strata, std::size_t face_samples,
                       std::size_t crease_samples, std::uint64_t seed) {
  SampleSet set;
  SampleWriter out(set);
  Random random(seed);
  add_vertex_samples(mesh, strata, out);
  add_edge_midpoints(mesh, strata, out);
  add_face_centroids(mesh, strata, out);
  add_random_on_faces(mesh, strata, face_samples, random, out);
  add_random_on_creases(mesh, strata, crease_samples, random, out);
  return set;
}

}  // namespace vorocrust::checker
