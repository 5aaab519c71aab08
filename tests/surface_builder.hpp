// Surfaces built in code from boxes and quads, for the tests of stages that take a SurfaceMesh.
#pragma once

#include <Eigen/Geometry>
#include <map>
#include <tuple>

#include "vorocrust/surface_mesh.hpp"

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

}  // namespace vorocrust::test
