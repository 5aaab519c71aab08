// The independent ball checker on ball sets made by hand: a correct one passes, and each
// condition broken on purpose is reported under that condition.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>

#include "check_balls/check_balls.hpp"
#include "check_balls/strata.hpp"
#include "surface_builder.hpp"
#include "test_support.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/read_mesh.hpp"
#include "vorocrust/validate.hpp"

namespace vorocrust::checker {
namespace {

constexpr double kCornerRadius = 0.2, kCreaseRadius = 0.15, kPatchRadius = 0.1;
constexpr int kGrid = 7;  // patch balls per face side

BallCheckOptions fast_options() {
  BallCheckOptions o;
  o.face_samples = 20000;
  o.crease_samples = 5000;
  o.max_listed = 100000;  // keep every example, so tests can look for the one they caused
  return o;
}

SurfaceMesh box_mesh() {
  SurfaceMesh mesh = read_mesh(test::model("sandia_OneBox.obj"));
  (void)validate(mesh);
  return mesh;
}

// sandia_OneBox is [1,2] x [0,1] x [0,1]. Corner balls of radius 0.2; crease balls of radius
// 0.15 at 1/4, 1/2, 3/4 of each edge (far enough from the corner that balls on two creases of one
// corner do not meet: 2 * 0.15 < 0.25 sqrt 2); a 7 x 7 grid of patch balls of radius 0.1 from
// 0.15 to 0.85 on each face (spacing 0.1167 < sqrt 2 (1 - alpha) 0.1, so the grid covers deeply,
// and 0.1 + 0.1 < 0.15 sqrt 2, so balls on two faces do not meet).
struct BoxBalls {
  std::vector<CheckedBall> balls;
  std::size_t first_crease = 0, first_patch = 0;

  BoxBalls() {
    const Point low(1, 0, 0);
    for (int i = 0; i < 8; ++i) {
      add(low + Point(i & 1, (i >> 1) & 1, (i >> 2) & 1), kCornerRadius, StratumType::Corner);
    }
    first_crease = balls.size();
    for (int axis = 0; axis < 3; ++axis) {
      for (int side = 0; side < 4; ++side) {
        Point start = low;
        start[(axis + 1) % 3] += side & 1;
        start[(axis + 2) % 3] += side >> 1;
        for (double s : {0.25, 0.5, 0.75}) add(start + s * Point::Unit(axis), kCreaseRadius, StratumType::Crease);
      }
    }
    first_patch = balls.size();
    for (int axis = 0; axis < 3; ++axis) {
      for (int side = 0; side < 2; ++side) {
        for (int i = 0; i < kGrid; ++i) {
          for (int j = 0; j < kGrid; ++j) add(patch_centre(axis, side, i, j), kPatchRadius, StratumType::Patch);
        }
      }
    }
  }

  static Point patch_centre(int axis, int side, int i, int j) {
    const auto t = [](int k) { return 0.15 + k * 0.7 / (kGrid - 1); };
    Point p(1, 0, 0);
    p[axis] += side;
    p[(axis + 1) % 3] += t(i);
    p[(axis + 2) % 3] += t(j);
    return p;
  }
  // The index of a patch ball: face (axis, side), grid position (i, j).
  std::size_t patch(int axis, int side, int i, int j) const {
    return first_patch + ((axis * 2 + side) * kGrid + i) * kGrid + j;
  }
  std::size_t add(const Point& centre, double radius, StratumType type) {
    // A deliberately wrong stratum index: the checker must match strata by geometry.
    balls.push_back({centre, radius, type, 999, 0});
    return balls.size() - 1;
  }
};

std::string text(const BallCheckReport& r) { return report_text(r); }

bool has_example(const BallCheckReport& r, Condition c, std::initializer_list<std::size_t> balls) {
  return std::any_of(r[c].examples.begin(), r[c].examples.end(), [&](const Violation& v) {
    return std::all_of(balls.begin(), balls.end(),
                       [&](std::size_t b) { return std::find(v.balls.begin(), v.balls.end(), b) != v.balls.end(); });
  });
}

TEST(CheckBallsStrata, UnitBoxHasEightCornersTwelveCreasesSixPatches) {
  const SurfaceMesh mesh = box_mesh();
  const Strata s = find_strata(mesh, 30 * std::numbers::pi / 180);
  EXPECT_EQ(s.num_corners(), 8u);
  EXPECT_EQ(s.num_creases(), 12u);
  EXPECT_EQ(s.num_patches, 6u);
  for (std::size_t c = 0; c < s.num_creases(); ++c) {
    EXPECT_EQ(s.crease_edges[c].size(), 1u);
    EXPECT_EQ(s.crease_corners[c].size(), 2u);
  }
  for (std::size_t p = 0; p < s.num_patches; ++p) {
    EXPECT_EQ(s.patch_creases[p].size(), 4u);
    EXPECT_EQ(s.patch_corners[p].size(), 4u);
  }
}

TEST(CheckBalls, CorrectBoxConfigurationPasses) {
  const BoxBalls box;
  const BallCheckReport r = check_balls(box_mesh(), box.balls, fast_options());
  EXPECT_TRUE(r.ok()) << text(r);
  EXPECT_EQ(r.corners, 8u);
  EXPECT_EQ(r.creases, 12u);
  EXPECT_EQ(r.patches, 6u);
  EXPECT_EQ(r.samples.on_faces, 20000u);
  EXPECT_EQ(r.samples.on_creases, 5000u);
  EXPECT_EQ(r.samples.vertices, 8u);
}

TEST(CheckBalls, BallReachingAnotherFaceBreaksC1) {
  BoxBalls box;
  const std::size_t big = box.patch(2, 0, 0, 3);  // 0.15 from the edge y = 0 of face z = 0
  box.balls[big].radius = 0.3;
  const BallCheckReport r = check_balls(box_mesh(), box.balls, fast_options());
  EXPECT_GT(r[Condition::C1].count, 0u) << text(r);
  EXPECT_TRUE(has_example(r, Condition::C1, {big})) << text(r);
}

TEST(CheckBalls, CornerBallContainingAnotherCornerBreaksC1) {
  BoxBalls box;
  box.balls[0].radius = 1.2;
  const BallCheckReport r = check_balls(box_mesh(), box.balls, fast_options());
  EXPECT_TRUE(has_example(r, Condition::C1, {0})) << text(r);
}

TEST(CheckBalls, OverlapAcrossAnEdgeBreaksC2) {
  BoxBalls box;
  // Each stays off the crease (0.09 < 0.1) but they meet across it: 0.1 sqrt 2 < 0.18.
  const std::size_t p = box.add({1.5, 0.1, 0}, 0.09, StratumType::Patch);
  const std::size_t q = box.add({1.5, 0, 0.1}, 0.09, StratumType::Patch);
  const BallCheckReport r = check_balls(box_mesh(), box.balls, fast_options());
  EXPECT_TRUE(has_example(r, Condition::C2, {p, q})) << text(r);
  EXPECT_FALSE(has_example(r, Condition::C1, {p})) << text(r);
}

TEST(CheckBalls, RadiusJumpBreaksC3) {
  BoxBalls box;
  const std::size_t small = box.patch(0, 1, 3, 3);
  box.balls[small].radius = 0.07;  // its neighbours at 0.1167 have 0.1 > 0.07 + 0.25 * 0.1167
  const BallCheckReport r = check_balls(box_mesh(), box.balls, fast_options());
  EXPECT_TRUE(has_example(r, Condition::C3, {box.patch(0, 1, 2, 3), small})) << text(r);
  EXPECT_EQ(r[Condition::C1].count, 0u) << text(r);
}

TEST(CheckBalls, CentresTooCloseBreakC4b) {
  BoxBalls box;
  const std::size_t near = box.add(box.balls[box.patch(1, 0, 3, 3)].centre + Point(0.01, 0, 0), kPatchRadius,
                                   StratumType::Patch);
  const BallCheckReport r = check_balls(box_mesh(), box.balls, fast_options());
  EXPECT_TRUE(has_example(r, Condition::C4b, {box.patch(1, 0, 3, 3), near})) << text(r);
  EXPECT_EQ(r[Condition::C1].count, 0u) << text(r);
}

TEST(CheckBalls, MissingPatchBallLeavesAHole) {
  BoxBalls box;
  const Point hole = box.balls[box.patch(2, 1, 3, 3)].centre;
  box.balls.erase(box.balls.begin() + static_cast<std::ptrdiff_t>(box.patch(2, 1, 3, 3)));
  const BallCheckReport r = check_balls(box_mesh(), box.balls, fast_options());
  EXPECT_GT(r[Condition::Coverage].count, 0u) << text(r);
  EXPECT_GT(r[Condition::C4a].count, 0u) << text(r);
  for (Condition c : {Condition::Coverage, Condition::C4a}) {
    for (const Violation& v : r[c].examples) {
      ASSERT_TRUE(v.point);
      EXPECT_LT((*v.point - hole).norm(), 0.1) << v.message;
    }
  }
  EXPECT_EQ(r[Condition::C1].count + r[Condition::C2].count + r[Condition::C3].count + r[Condition::C4b].count, 0u);
}

TEST(CheckBalls, ShallowCoverageBreaksC4aOnly) {
  BoxBalls box;
  // Spread one face's grid so points between balls are covered, but not deeply.
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) box.balls[box.patch(0, 0, i, j)].radius = 0.085;
  }
  const BallCheckReport r = check_balls(box_mesh(), box.balls, fast_options());
  EXPECT_GT(r[Condition::C4a].count, 0u) << text(r);
  EXPECT_EQ(r[Condition::Coverage].count, 0u) << text(r);
}

TEST(CheckBalls, MissingCornerBallBreaksProtection) {
  BoxBalls box;
  box.balls.erase(box.balls.begin());  // the corner (1, 0, 0)
  const BallCheckReport r = check_balls(box_mesh(), box.balls, fast_options());
  const auto& examples = r[Condition::Protection].examples;
  EXPECT_TRUE(std::any_of(examples.begin(), examples.end(), [](const Violation& v) {
    return v.point && *v.point == Point(1, 0, 0) && v.message.find("has no corner ball") != std::string::npos;
  })) << text(r);
}

TEST(CheckBalls, CreaseBallOffItsCreaseBreaksProtection) {
  BoxBalls box;
  const std::size_t moved = box.first_crease + 1;  // the middle ball of the first edge, along x
  box.balls[moved].centre += Point(0, 0.01, 0);
  const BallCheckReport r = check_balls(box_mesh(), box.balls, fast_options());
  EXPECT_TRUE(has_example(r, Condition::Protection, {moved})) << text(r);
  const auto& examples = r[Condition::Protection].examples;
  EXPECT_TRUE(std::any_of(examples.begin(), examples.end(), [](const Violation& v) {
    return v.message.find("not on a crease") != std::string::npos;
  })) << text(r);
}

TEST(CheckBalls, BallOfTheWrongTypeBreaksProtection) {
  BoxBalls box;
  const std::size_t wrong = box.first_patch + 3;
  box.balls[wrong].type = StratumType::Crease;  // a patch ball's centre, called a crease ball
  const BallCheckReport r = check_balls(box_mesh(), box.balls, fast_options());
  EXPECT_TRUE(has_example(r, Condition::Protection, {wrong})) << text(r);
}

TEST(CheckBalls, EqualSeedsGiveEqualReports) {
  BoxBalls box;
  box.balls.erase(box.balls.begin() + static_cast<std::ptrdiff_t>(box.patch(2, 1, 3, 3)));
  const SurfaceMesh mesh = box_mesh();
  const BallCheckReport a = check_balls(mesh, box.balls, fast_options());
  const BallCheckReport b = check_balls(mesh, box.balls, fast_options());
  EXPECT_EQ(a[Condition::Coverage].count, b[Condition::Coverage].count);
  EXPECT_EQ(a[Condition::C4a].count, b[Condition::C4a].count);
}

// One ball per vertex, all of one radius between what deep coverage needs (every triangle's
// circumradius within (1 - alpha) r) and what C4b allows (every edge at least (1 - alpha) r).
std::vector<CheckedBall> vertex_balls(const SurfaceMesh& mesh) {
  double shortest = 1e300, widest = 0;
  for (const Triangle& f : mesh.triangles) {
    const Point &a = mesh.vertices[f[0]], &b = mesh.vertices[f[1]], &c = mesh.vertices[f[2]];
    const double ab = (b - a).norm(), bc = (c - b).norm(), ca = (a - c).norm();
    shortest = std::min({shortest, ab, bc, ca});
    widest = std::max(widest, ab * bc * ca / (2 * (b - a).cross(c - a).norm()));  // circumradius
  }
  const double keep = 1 - deep_coverage_alpha();
  EXPECT_LT(widest, shortest);
  const double radius = 0.5 * (widest / keep + shortest / keep);
  std::vector<CheckedBall> balls;
  for (const Point& p : mesh.vertices) balls.push_back({p, radius, StratumType::Patch, 0, 0});
  return balls;
}

TEST(CheckBalls, CorrectSmoothConfigurationPasses) {
  const SurfaceMesh sphere = test::icosphere(3);
  const BallCheckReport r = check_balls(sphere, vertex_balls(sphere), fast_options());
  EXPECT_EQ(r.corners + r.creases, 0u);
  EXPECT_EQ(r.patches, 1u);
  EXPECT_TRUE(r.ok()) << text(r);
}

TEST(CheckBalls, BallTooBigForTheCurvatureBreaksC1) {
  const SurfaceMesh sphere = test::icosphere(3);
  std::vector<CheckedBall> balls = vertex_balls(sphere);
  balls[5].radius = 1.0;  // holds points whose normals turn by 60 degrees
  const BallCheckReport r = check_balls(sphere, balls, fast_options());
  EXPECT_TRUE(has_example(r, Condition::C1, {5})) << text(r);
  EXPECT_TRUE(has_example(r, Condition::C3, {5})) << text(r);
  const auto& examples = r[Condition::C1].examples;
  EXPECT_TRUE(std::any_of(examples.begin(), examples.end(), [](const Violation& v) {
    return v.message.find("turn by more than") != std::string::npos;
  })) << text(r);
}

TEST(CheckBallsCsv, RoundTripIsExact) {
  test::TempDir dir("check-balls");
  BoxBalls box;
  box.balls[3].centre = Point(1.0 / 3, 2.0 / 7, 1e-17);
  write_balls_csv(dir / "balls.csv", box.balls);
  const std::vector<CheckedBall> back = read_balls_csv(dir / "balls.csv");
  ASSERT_EQ(back.size(), box.balls.size());
  for (std::size_t i = 0; i < back.size(); ++i) {
    EXPECT_EQ(back[i].centre, box.balls[i].centre);
    EXPECT_EQ(back[i].radius, box.balls[i].radius);
    EXPECT_EQ(back[i].type, box.balls[i].type);
    EXPECT_EQ(back[i].stratum_index, box.balls[i].stratum_index);
    EXPECT_EQ(back[i].line, i + 2);
  }
}

TEST(CheckBallsCsv, MalformedLinesAreNamedByFileAndLine) {
  test::TempDir dir("check-balls");
  const std::string header = "x,y,z,radius,stratum_type,stratum_index\n";
  const std::string good = "1,0,0,0.2,corner,0\n";
  const std::vector<std::pair<std::string, std::size_t>> cases = {
      {header + good + "1,0,zero,0.2,corner,0\n", 3},        // not a number
      {header + good + "\n1,0,0,0.2,corner\n", 4},           // a field missing, after a blank line
      {header + good + "1,0,0,-0.2,corner,0\n", 3},          // negative radius
      {header + good + "1,0,0,0.2,edge,0\n", 3},             // unknown stratum type
      {header + good + "1,0,0,0.2,crease,-1\n", 3},          // negative index
      {header + "1,0,nan,0.2,crease,1\n", 2},                // not finite
      {"x,y,z,r,type,index\n" + good, 1},                    // wrong header
      {"", 1},                                               // empty
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto path = dir / ("bad" + std::to_string(i) + ".csv");
    std::ofstream(path) << cases[i].first;
    try {
      (void)read_balls_csv(path);
      ADD_FAILURE() << "case " << i << " was accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::UnreadableInput) << i;
      EXPECT_EQ(e.where().file, path.string()) << i;
      EXPECT_EQ(e.where().line, cases[i].second) << i << ": " << e.what();
      EXPECT_NE(std::string(e.what()).find(path.filename().string() + ":" + std::to_string(cases[i].second)),
                std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace vorocrust::checker
