// check_balls/check_balls.hpp — a brute-force oracle for the ball conditions.
//
// Contract (docs/ball-conditions.md): given a surface (read and validated, so face orientation is
// consistent) and a set of balls, check_balls() reports every violation of C1 (smooth coverage),
// C2 (smooth overlaps), C3 (Lipschitz radii), C4a (deep coverage of the surface), C4b (no two
// centres deeply inside each other), plain coverage and protection (corners carry corner balls,
// each ball lies on a stratum of its type, creases are covered by corner and crease balls).
//
// The checker derives the strata itself and tests the surface through dense samples (every vertex,
// edge midpoint and face centroid, plus reproducible random points on faces and sharp edges).
// It shares no code with the refinement; the stratum indices in the ball list are ignored and each
// centre is matched to a stratum by geometry. Pair conditions (C2, C3, C4b) and the placement of
// centres are checked exactly, for every pair and ball; surface conditions (C1, C4a, coverage) at
// the samples only, so each one reported names a real point, and a clean report means that no
// sample found one.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::checker {

// Ordered by dimension: a corner is a point, a crease a curve, a patch a surface.
enum class StratumType : std::uint8_t { Corner = 0, Crease = 1, Patch = 2 };

const char* to_string(StratumType type) noexcept;
inline int dimension(StratumType type) noexcept { return static_cast<int>(type); }

// One ball of the refinement's output, as balls.csv lists it.
struct CheckedBall {
  Point centre = Point::Zero();
  double radius = 0;
  StratumType type = StratumType::Patch;
  std::uint64_t stratum_index = 0;  // the refinement's numbering; informative only
  std::size_t line = 0;             // line in balls.csv, 0 when not read from a file
};

// Reads balls.csv (header `x,y,z,radius,stratum_type,stratum_index`, then one ball a line; blank
// lines are skipped). Throws Error(UnreadableInput) naming the file and line of the first line
// that is malformed: wrong field count, a number that does not parse or is not finite, a radius
// that is not positive, an unknown stratum type.
std::vector<CheckedBall> read_balls_csv(const std::filesystem::path& path);

// Writes balls in the same format with 17 significant digits, so they read back exactly.
void write_balls_csv(const std::filesystem::path& path, const std::vector<CheckedBall>& balls);

struct BallCheckOptions {
  double sharp_angle_degrees = 30;  // theta; the CLI takes its default from MeshOptions
  double lipschitz = 0.25;          // L
  std::size_t face_samples = 200000;  // random points on faces, proportional to area
  std::size_t crease_samples = 50000; // random points on sharp edges, proportional to length
  std::uint64_t seed = 1;             // equal seeds sample equal points
  std::size_t max_listed = 20;        // violations kept as examples per condition

  // Throws Error(Usage) naming the first option out of range.
  void check() const;
};

enum class Condition : std::uint8_t { C1, C2, C3, C4a, C4b, Coverage, Protection };
inline constexpr std::size_t kConditionCount = 7;

const char* to_string(Condition condition) noexcept;  // "C1", ..., "coverage", "protection"
const char* title(Condition condition) noexcept;      // "smooth coverage", ...

struct Violation {
  Condition condition = Condition::C1;
  std::vector<std::size_t> balls;  // 0-based indices into the ball list
  std::optional<Point> point;      // the surface sample or corner concerned, if any
  std::string stratum;             // that point's stratum in the checker's numbering, "crease 3"
  std::string message;             // one line with the numbers
};

// What one violation is: C1 a (ball, sample) pair; C2 and C4b an unordered pair of balls; C3 an
// ordered pair (the ball too large, the one it is compared with); C4a and coverage a sample;
// protection a misplaced ball centre, a corner without a corner ball, or a crease sample in no
// corner or crease ball.
struct ConditionResult {
  std::size_t count = 0;            // every violation found
  std::vector<Violation> examples;  // the first few, one per ball where balls are involved
};

struct SampleCounts {
  std::size_t vertices = 0, edge_midpoints = 0, face_centroids = 0, on_faces = 0, on_creases = 0;
  std::size_t total() const { return vertices + edge_midpoints + face_centroids + on_faces + on_creases; }
};

struct BallCheckReport {
  std::array<ConditionResult, kConditionCount> conditions;
  std::size_t corners = 0, creases = 0, patches = 0;
  std::array<std::size_t, 3> balls_by_type{};  // indexed by StratumType
  SampleCounts samples;
  double diagonal = 0;       // of the surface's bounding box
  double sharp_angle_degrees = 0, lipschitz = 0, alpha = 0;
  double seconds = 0;

  const ConditionResult& operator[](Condition c) const { return conditions[static_cast<std::size_t>(c)]; }
  ConditionResult& operator[](Condition c) { return conditions[static_cast<std::size_t>(c)]; }
  std::size_t violations() const;
  bool ok() const { return violations() == 0; }
};

// alpha = 1 - sqrt(3)/2, paper 2.3.
double deep_coverage_alpha();

// Throws Error(Usage) for options out of range or a ball without a finite centre and positive
// radius, Error(InvalidGeometry) for a mesh without triangles.
BallCheckReport check_balls(const SurfaceMesh& mesh, const std::vector<CheckedBall>& balls,
                            const BallCheckOptions& options = {});

// Human-readable and JSON renderings of a report.
std::string report_text(const BallCheckReport& report);
std::string report_json(const BallCheckReport& report);

}  // namespace vorocrust::checker
