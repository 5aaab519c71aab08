// The union-cover tests against brute force over dense points of the piece.
#include <gtest/gtest.h>

#include <random>

#include "refinement/union_cover.hpp"

namespace vorocrust {
namespace {

bool brute_segment(const Point& a, const Point& b, const std::vector<CoverBall>& balls) {
  for (int i = 0; i <= 2000; ++i) {
    const Point p = a + (i / 2000.0) * (b - a);
    bool in = false;
    for (const CoverBall& c : balls) in = in || (p - c.centre).norm() <= c.radius;
    if (!in) return false;
  }
  return true;
}

bool brute_triangle(const Point& a, const Point& b, const Point& c, const std::vector<CoverBall>& balls) {
  constexpr int n = 120;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; i + j <= n; ++j) {
      const Point p = a + (double(i) / n) * (b - a) + (double(j) / n) * (c - a);
      bool in = false;
      for (const CoverBall& ball : balls) in = in || (p - ball.centre).norm() <= ball.radius;
      if (!in) return false;
    }
  }
  return true;
}

TEST(UnionCover, SegmentAgreesWithBruteForce) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1), r(0.2, 0.9);
  int covered = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const Point a(0, 0, 0), b(2, 0, 0);
    std::vector<CoverBall> balls;
    for (int k = 0; k < 3; ++k) balls.push_back({Point(1 + u(rng), 0.3 * u(rng), 0.3 * u(rng)), r(rng)});
    const bool exact = segment_covered(a, b, balls);
    covered += exact;
    // Brute force can only miss gaps narrower than its spacing: it may say covered when exact says not.
    if (exact) {
      EXPECT_TRUE(brute_segment(a, b, balls)) << trial;
    }
  }
  EXPECT_GT(covered, 50);
}

TEST(UnionCover, TriangleAgreesWithBruteForce) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1), r(0.25, 0.8);
  int covered = 0, disagreements = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const Point a(0, 0, 0), b(1, 0, 0), c(0.2, 0.9, 0);
    std::vector<CoverBall> balls;
    const int count = 2 + trial % 4;  // two to five balls around the triangle
    for (int k = 0; k < count; ++k) balls.push_back({Point(0.4 + 0.6 * u(rng), 0.4 + 0.6 * u(rng), 0.3 * u(rng)), r(rng)});
    const bool exact = triangle_covered(a, b, c, balls);
    const bool brute = brute_triangle(a, b, c, balls);
    covered += exact;
    if (exact) {
      ASSERT_TRUE(brute) << "claimed covered but a point is outside, trial " << trial;
    } else {
      disagreements += brute;  // brute force misses only gaps thinner than its spacing
    }
  }
  EXPECT_GT(covered, 200);
  EXPECT_LT(disagreements, 30);
}

// Balls on the corners of an equilateral triangle, just reaching its centre: all three cover
// it, no two do.
TEST(UnionCover, TriangleNeedsThreeBalls) {
  const Point a(0, 0, 0), b(1, 0, 0), c(0.5, 0.8660254037844386, 0);
  std::vector<CoverBall> balls;
  for (const Point& corner : {a, b, c}) balls.push_back({corner, 0.6});  // the centre is 0.577 away
  EXPECT_TRUE(triangle_covered(a, b, c, balls));
  EXPECT_TRUE(brute_triangle(a, b, c, balls));
  for (int skip = 0; skip < 3; ++skip) {
    std::vector<CoverBall> two;
    for (int k = 0; k < 3; ++k) {
      if (k != skip) two.push_back(balls[k]);
    }
    EXPECT_FALSE(triangle_covered(a, b, c, two));
  }
}

}  // namespace
}  // namespace vorocrust
