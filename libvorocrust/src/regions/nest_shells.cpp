#include "regions/nest_shells.hpp"

#include <algorithm>
#include <map>
#include <optional>

#include "core/face_components.hpp"
#include "core/surface_measures.hpp"
#include "core/union_find.hpp"

namespace vorocrust::regions {

namespace {

// Faces of a part that rays from afar aim at before the part's outer shell is guessed by volume.
constexpr std::size_t kAimedFaces = 8;

Point generic_direction(std::size_t k) {
  const auto& g = geometry::kGenericDirections[k % geometry::kGenericDirections.size()];
  return Point(g[0], g[1], g[2]).normalized();
}

class Nesting {
 public:
  Nesting(const SurfaceMesh& mesh, const EdgeTopology& topology, const Shells& shells, const geometry::RayCaster& rays)
      : mesh_(mesh), shells_(shells), rays_(rays), parts_(face_components(mesh, topology)),
        volume_(shell_volumes(mesh, shells)) {
    for (const Point& p : mesh.vertices) bounds_.include(p);
    // Rays aim at a part's largest faces, whose centroids lie well inside them: those come first
    // (ties by index, as the part lists its faces).
    std::vector<double> areas(mesh.num_faces());
    for (Index f = 0; f < mesh.num_faces(); ++f) areas[f] = face_area(mesh, f);
    const auto larger = [&](Index a, Index b) { return areas[a] > areas[b] || (areas[a] == areas[b] && a < b); };
    for (auto& faces : parts_.faces) {
      std::partial_sort(faces.begin(), faces.begin() + std::min(faces.size(), kAimedFaces), faces.end(), larger);
    }
  }

  ShellRegions regions() {
    const std::size_t unbounded = shells_.count;
    UnionFind joined(shells_.count + 1);
    std::vector<bool> outer(shells_.count, false);
    std::vector<Index> outer_of_part(parts_.faces.size());
    for (std::size_t c = 0; c < parts_.faces.size(); ++c) {
      outer_of_part[c] = outer_shell(static_cast<Index>(c));
      outer[outer_of_part[c]] = true;
    }
    for (std::size_t c = 0; c < parts_.faces.size(); ++c) {
      const std::optional<Index> around = parts_.faces.size() > 1 ? container(static_cast<Index>(c), outer) : std::nullopt;
      joined.unite(outer_of_part[c], static_cast<std::uint32_t>(around ? *around : unbounded));
    }
    ShellRegions result;
    result.of_shell.resize(shells_.count);
    std::map<std::uint32_t, Index> number;
    number[joined.find(static_cast<std::uint32_t>(unbounded))] = 0;
    result.count = 1;
    for (std::size_t s = 0; s < shells_.count; ++s) {
      const auto [it, fresh] = number.try_emplace(joined.find(static_cast<std::uint32_t>(s)), static_cast<Index>(result.count));
      if (fresh) ++result.count;
      result.of_shell[s] = it->second;
    }
    return result;
  }

 private:
  Index shell_facing(const geometry::RayHit& hit) const {
    return shells_.of_side[hit.from_front ? front_side(hit.face) : back_side(hit.face)];
  }

  // The shell of part c seen from afar: the side of the part's first face met by a ray coming
  // from outside the whole surface's bounding box.
  Index outer_shell(Index c) const {
    const double reach = 2 * (bounds_.hi - bounds_.lo).norm() + 1;
    const std::vector<Index>& faces = parts_.faces[c];
    for (std::size_t k = 0; k < std::min(faces.size(), kAimedFaces); ++k) {
      const Point target = face_centroid(mesh_, faces[k]);
      for (std::size_t d = 0; d < geometry::kGenericDirections.size(); ++d) {
        const Point direction = generic_direction(d);
        const Point origin = target + reach * direction;  // outside the bounding box
        for (const geometry::RayHit& hit : rays_.all_hits(origin, -direction)) {
          if (parts_.of_face[hit.face] != c) continue;
          if (hit.clear) return shell_facing(hit);
          break;
        }
      }
    }
    // Every ray grazed an edge: the shell enclosing the most, seen from outside, is the outer one.
    Index best = shells_.of_side[back_side(faces.front())];
    for (Index f : faces) {
      for (std::size_t side : {back_side(f), front_side(f)}) {
        if (volume_[shells_.of_side[side]] < volume_[best]) best = shells_.of_side[side];
      }
    }
    return best;
  }

  // The innermost bounded shell of another part around part c, if any.
  std::optional<Index> container(Index c, const std::vector<bool>& outer) const {
    const std::vector<Index>& faces = parts_.faces[c];
    const Point from = face_centroid(mesh_, faces.front());
    std::optional<std::vector<geometry::RayHit>> chosen;
    for (std::size_t d = 0; d < geometry::kGenericDirections.size() && !chosen; ++d) {
      std::vector<geometry::RayHit> hits = rays_.all_hits(from, generic_direction(d));
      std::erase_if(hits, [&](const geometry::RayHit& h) { return parts_.of_face[h.face] == c; });
      if (std::all_of(hits.begin(), hits.end(), [](const geometry::RayHit& h) { return h.clear; }) ||
          d + 1 == geometry::kGenericDirections.size()) {
        chosen = std::move(hits);
      }
    }
    // A face whose two sides lie on one shell is crossed twice by it: no change of parity.
    std::map<Index, bool> odd;
    for (const geometry::RayHit& hit : *chosen) {
      odd[shells_.of_side[back_side(hit.face)]] ^= true;
      odd[shells_.of_side[front_side(hit.face)]] ^= true;
    }
    std::optional<Index> innermost;
    for (const auto& [shell, crossed] : odd) {
      if (!crossed || outer[shell]) continue;
      if (!innermost || volume_[shell] < volume_[*innermost]) innermost = shell;
    }
    return innermost;
  }

  const SurfaceMesh& mesh_;
  const Shells& shells_;
  const geometry::RayCaster& rays_;
  FaceComponents parts_;
  std::vector<double> volume_;
  geometry::Box bounds_;
};

}  // namespace

ShellRegions nest_shells(const SurfaceMesh& mesh, const EdgeTopology& topology, const Shells& shells,
                         const geometry::RayCaster& rays) {
  return Nesting(mesh, topology, shells, rays).regions();
}

}  // namespace vorocrust::regions
