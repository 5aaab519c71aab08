// The largest inscribed ball as a linear program in (centre, radius): every plane keeps the
// centre at least the radius inside.
#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/fixed_shuffle.hpp"
#include "geometry/small_lp.hpp"
#include "geometry/spheres.hpp"

namespace vorocrust::geometry {

Sphere largest_inscribed_ball(const std::vector<Plane>& planes, const Point& inside, double extent) {
  // In the frame where `inside` is the origin and the extent 1; the box |x_i| <= 2 then bounds
  // the program without touching its optimum.
  std::vector<HalfSpace> constraints;
  constraints.reserve(planes.size());
  for (const Plane& p : planes) {
    HalfSpace h;
    h.a = {p.normal.x(), p.normal.y(), p.normal.z(), 1.0};
    h.b = (p.offset - p.normal.dot(inside)) / extent;
    constraints.push_back(h);
  }
  // Nearest planes first: they are the ones likely to touch the ball, and once they are in,
  // the others seldom move the optimum (twice as fast as a random order on lattice cells). The
  // fixed shuffle orders equal distances, as a cube's six are.
  fixed_shuffle(constraints);
  std::stable_sort(constraints.begin(), constraints.end(),
                   [](const HalfSpace& a, const HalfSpace& b) { return a.b < b.b; });
  const std::optional<LpVector> x = maximise(4, {0, 0, 0, 1}, constraints, 2.0);
  if (!x || !((*x)[3] > 0)) return {inside, 0};
  const Point centre = inside + extent * Point((*x)[0], (*x)[1], (*x)[2]);
  double radius = std::numeric_limits<double>::infinity();
  for (const Plane& p : planes) radius = std::min(radius, p.offset - p.normal.dot(centre));
  return {centre, std::max(radius, 0.0)};
}

}  // namespace vorocrust::geometry
