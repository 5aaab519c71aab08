// Skinny surface triangles (paper 2.4, with Delaunay refinement's circumcentre rule).
#include "seeds/skinny_triangles.hpp"

#include <algorithm>

#include "quality/triangle_shape.hpp"

namespace vorocrust {

namespace {

// As sliver elimination's: a ball shrunk to the distance itself would leave the circumcentre on
// its sphere, where the next sample may not land.
constexpr double kClearance = 0.05;

// The circumcentre of a non-degenerate triangle, in its plane.
Point circumcentre(const Point& a, const Point& b, const Point& c) {
  const Point ab = b - a, ac = c - a;
  const Point n = ab.cross(ac);
  return a + (ac.squaredNorm() * n.cross(ab) + ab.squaredNorm() * ac.cross(n)) / (2 * n.squaredNorm());
}

}  // namespace

SkinnyTriangleShrinks choose_skinny_triangle_shrinks(const BallIndex& balls, const std::vector<SeedPair>& pairs,
                                                     double min_angle_degrees, double deep_coverage) {
  SkinnyTriangleShrinks out;
  BallShrinkRequests requests;
  std::vector<std::uint32_t> near;
  for (const SeedPair& pair : pairs) {
    const RefinedBall &a = balls[pair.balls[0]], &b = balls[pair.balls[1]], &c = balls[pair.balls[2]];
    if (a.site.type != StratumType::Patch || b.site.type != StratumType::Patch || c.site.type != StratumType::Patch) continue;
    const TriangleShape shape = triangle_shape(a.site.position, b.site.position, c.site.position);
    if (!(*std::min_element(shape.angles_degrees.begin(), shape.angles_degrees.end()) < min_angle_degrees)) continue;
    ++out.skinny;
    if (!(shape.quality > 0)) continue;  // no circumcentre; overlapping balls never make one
    const Point x = circumcentre(a.site.position, b.site.position, c.site.position);
    near.clear();
    balls.reaching(StratumType::Patch, x, 0.0, near);
    for (std::uint32_t q : near) {
      const double d = (balls[q].site.position - x).norm();
      if (d < deep_coverage * balls[q].radius) requests.ask(q, d / deep_coverage * (1 - kClearance));
    }
  }
  out.shrinks = requests.result(balls);
  return out;
}

}  // namespace vorocrust
