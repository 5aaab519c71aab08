// check_balls/samples.hpp — dense, reproducible samples of the surface, each on one stratum.
//
// Contract: make_samples() returns every vertex, every edge midpoint, every face centroid, then
// `face_samples` uniform random points on faces (chosen proportionally to area) and
// `crease_samples` on sharp edges (proportionally to length), from a fixed-seed generator of our
// own so equal seeds give equal samples on every platform.
//
// Each sample carries its stratum and its candidate directions (docs/ball-conditions.md): a point
// on one face has that face's normal; a point on several faces of its stratum (a vertex, a
// non-sharp edge) is on each of them, so it carries all their normals and the co-smoothness test
// accepts it when any one of them passes. Stratum membership:
// - a corner vertex is on its corner (no direction);
// - a non-corner vertex on a sharp edge is on that crease, with both crease edges' directions;
// - any other vertex is on each patch among its faces, one sample per patch;
// - a point on a sharp edge (midpoint or random) is on that edge's crease, never on the patches
//   beside it;
// - everything else is on the patch of its face(s).
// Faces of zero area give no direction; samples left with none are dropped.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "check_balls/strata.hpp"

namespace vorocrust::checker {

enum class SampleSource : std::uint8_t { Vertex, EdgeMidpoint, FaceCentroid, RandomOnFace, RandomOnCrease };

const char* to_string(SampleSource source) noexcept;

struct Sample {
  Point position;
  StratumRef stratum;
  Index first_direction = 0;
  Index direction_count = 0;
  SampleSource source = SampleSource::Vertex;
  Index element = 0;  // the vertex, edge or face it came from
};

struct SampleSet {
  std::vector<Sample> samples;
  std::vector<Point> directions;
  SampleCounts counts;

  std::span<const Point> directions_of(const Sample& s) const {
    return {directions.data() + s.first_direction, s.direction_count};
  }
};

SampleSet make_samples(const SurfaceMesh& mesh, const Strata& strata, std::size_t face_samples,
                       std::size_t crease_samples, std::uint64_t seed);

}  // namespace vorocrust::checker
