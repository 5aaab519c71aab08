// Surfaces built in code from boxes, quads and a subdivided icosahedron, for the tests of stages that
// take a SurfaceMesh.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

#include "vorocrust/surface_mesh.hpp"
#include "vorocrust/validate.hpp"

namespace vorocrust::test {

// Vertices with exactly equal coordinates are shared, so boxes touching along a face or an edge
// share those faces' vertices.
class SurfaceBuilder {
 public:
  SurfaceBuilder() { mesh.groups.push_back({"built", ""}); }

  Index vertex(double x, double y, double z) {
    const auto [it, fresh] = index_.try_emplace({x, y, z}, static_cast<Index>(mesh.vertices.size()));
    if (fresh) mesh.vertices.emplace_back(x, y, z);
    return it->second;
  }
  // Quad a b c d as two triangles, normal by the right-hand rule.
  void quad(const Point& a, const Point& b, const Point& c, const Point& d) {
    const Index ia = vertex(a.x(), a.y(), a.z()), ib = vertex(b.x(), b.y(), b.z()), ic = vertex(c.x(), c.y(), c.z()),
                id = vertex(d.x(), d.y(), d.z());
    mesh.add_triangle({ia, ib, ic}, 0);
    mesh.add_triangle({ia, ic, id}, 0);
  }
  // The six sides of [lo, hi] moved by `placement` (a rigid motion), normals out; `skip_high_x`
  // leaves out the side x = hi.x (for walls).
  void box(const Point& lo, const Point& hi, bool skip_high_x = false,
           const Eigen::Isometry3d& placement = Eigen::Isometry3d::Identity()) {
    const auto p = [&](int i) {
      return Point(placement * Point(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z()));
    };
    quad(p(0), p(4), p(6), p(2));
    if (!skip_high_x) quad(p(1), p(3), p(7), p(5));
    quad(p(0), p(1), p(5), p(4));
    quad(p(2), p(6), p(7), p(3));
    quad(p(0), p(2), p(3), p(1));
    quad(p(4), p(5), p(7), p(6));
  }

  SurfaceMesh mesh;

 private:
  std::map<std::tuple<double, double, double>, Index> index_;
};

// A smooth model: a subdivided icosahedron on the unit sphere (20 * 4^subdivisions faces), one
// patch, no creases, validated.
inline SurfaceMesh icosphere(int subdivisions) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Point> v = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                          {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  std::vector<Triangle> t = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                             {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (Point& p : v) p.normalize();
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<Index, Index>, Index> middle;
    auto mid = [&](Index a, Index b) {
      const auto key = std::minmax(a, b);
      auto [it, fresh] = middle.try_emplace({key.first, key.second}, static_cast<Index>(v.size()));
      if (fresh) v.push_back((v[a] + v[b]).normalized());
      return it->second;
    };
    std::vector<Triangle> finer;
    for (const Triangle& f : t) {
      const Index ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      finer.insert(finer.end(), {{f[0], ab, ca}, {f[1], bc, ab}, {f[2], ca, bc}, {ab, bc, ca}});
    }
    t = std::move(finer);
  }
  SurfaceMesh mesh;
  mesh.vertices = v;
  mesh.groups.push_back({"sphere", ""});
  for (const Triangle& f : t) mesh.add_triangle(f, 0);
  (void)validate(mesh);
  return mesh;
}

}  // namespace vorocrust::test
