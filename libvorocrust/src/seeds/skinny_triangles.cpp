// Skinny surface triangles (paper 2.4, with Delaunay refinement's circumcentre rule).
#include "seeds/skinny_triangles.hpp"

#include <algorithm>

#include "geometry/triangle_shape.hpp"

namespace vorocrust {

namespace {

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
    const geometry::TriangleShape shape = geometry::triangle_shape(a.site.position, b.site.position, c.site.position);
    if (!(*std::min_element(shape.angles_degrees.begin(), shape.angles_degrees.end()) < min_angle_degrees)) continue;
    ++out.skinny;
    if (!(shape.quality > 0)) continue;  // no circumcentre; overlapping balls never make one
    const Point x = circumcentre(a.site.position, b.site.position, c.site.position);
    // Inside a crease or corner ball a point counts as covered for patches: no patch ball
    // shrunk would let a sample land there.
    near.clear();
    balls.reaching(StratumType::Corner, x, 0.0, near);
    balls.reaching(StratumType::Crease, x, 0.0, near);
    if (!near.empty()) continue;
    balls.reaching_scaled(StratumType::Patch, x, deep_coverage, 0.0, near);
    for (std::uint32_t q : near) {
      // A circumcentre far off (an obtuse triangle) can lie in a ball of another patch, across
      // a thin wall; that ball has nothing to do with the triangle.
      const Index patch = balls[q].site.stratum;
      if (patch != a.site.stratum && patch != b.site.stratum && patch != c.site.stratum) continue;
      const double d = (balls[q].site.position - x).norm();
      requests.ask(q, d / deep_coverage * (1 - kShrinkClearance));
    }
  }
  out.shrinks = requests.result(balls);
  return out;
}

}  // namespace vorocrust
