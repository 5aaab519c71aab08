// Self-intersection search: a bounding-volume hierarchy over the faces' boxes proposes the
// candidate pairs, the exact triangle test of triangle_intersection.hpp decides them.
#include "geometry/self_intersections.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <limits>

#include "geometry/box_tree.hpp"
#include "geometry/triangle_intersection.hpp"

namespace vorocrust::geometry {
std::vector<FacePair> find_self_intersections(const SurfaceMesh& mesh) {
  const std::size_t num_faces = mesh.num_faces();
  std::vector<Box> boxes(num_faces);
  std::vector<char> testable(num_faces, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, num_faces, 1024), [&](const auto& range) {
    for (std::size_t f = range.begin(); f != range.end(); ++f) {
      const Triangle& t = mesh.triangles[f];
      if (t[0] >= mesh.num_vertices() || t[1] >= mesh.num_vertices() || t[2] >= mesh.num_vertices())
        continue;
      const TriangleCorners corners = corners_of(mesh, f);
      if (is_degenerate(corners)) continue;
      testable[f] = 1;
      for (const Point& p : corners) boxes[f].include(p);
    }
  });

  std::vector<std::uint32_t> items;
  Box bounds;
  for (std::size_t f = 0; f < num_faces; ++f) {
    if (!testable[f]) continue;
    items.push_back(static_cast<std::uint32_t>(f));
    bounds.include(boxes[f]);
  }
  if (items.empty()) return {};
  const BoxTree tree(boxes, std::move(items));  // copies the boxes; `boxes` stays for the queries
  // Boxes are exact (min and max round nothing), so closed overlap tests already keep faces
  // that merely touch; the margin only guards that property against future box rounding.
  const double margin = 1e-12 * (bounds.hi - bounds.lo).norm();

  tbb::enumerable_thread_specific<std::vector<FacePair>> found;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, num_faces, 256), [&](const auto& range) {
    std::vector<FacePair>& out = found.local();
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      if (!testable[i]) continue;
      Box query = boxes[i];
      query.lo.array() -= margin;
      query.hi.array() += margin;
      const TriangleCorners t = corners_of(mesh, i);
      tree.for_each_overlap(query, [&](std::uint32_t j) {
        if (j <= i) return;  // each pair once, from its smaller face
        // Duplicate faces share all three corners, which improperly_intersect declines.
        const SharedCorners shared = shared_corners(mesh.triangles[i], mesh.triangles[j]);
        if (improperly_intersect(t, corners_of(mesh, j), shared)) out.emplace_back(i, j);
      });
    }
  });

  std::vector<FacePair> pairs;
  for (const std::vector<FacePair>& part : found)
    pairs.insert(pairs.end(), part.begin(), part.end());
  // Threads finish in any order; sorting makes the result deterministic.
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace vorocrust::geometry
