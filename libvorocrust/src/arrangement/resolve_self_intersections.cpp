// A surface that cuts through itself made into one that meets itself along shared edges:
// arrangement, before the features (2.2), so that intersection curves become creases.
#include "vorocrust/resolve_self_intersections.hpp"

#include <algorithm>
#include <deque>
#include <functional>
#include <map>
#include <string>

#include "arrangement/face_cuts.hpp"
#include "arrangement/triangulate_cut_face.hpp"
#include "core/edge_topology.hpp"
#include "geometry/ray_cast.hpp"
#include "geometry/self_intersections.hpp"
#include "regions/nest_shells.hpp"
#include "regions/shells.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/regions.hpp"

namespace vorocrust {
namespace {

using regions::back_side;
using regions::front_side;

double area(const SurfaceMesh& mesh, Index f) {
  const Triangle& t = mesh.triangles[f];
  return 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).norm();
}

// The input's faces with those that cross cut into pieces; parent[f] is the input face of piece f.
SurfaceMesh cut_faces(const SurfaceMesh& mesh, const arrangement::FaceCuts& cuts, std::vector<Index>& parent) {
  SurfaceMesh arranged;
  arranged.vertices = cuts.points;
  arranged.groups = mesh.groups;
  std::size_t next_cut = 0;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const Index group = f < mesh.face_group.size() ? mesh.face_group[f] : 0;
    const std::uint32_t line = f < mesh.face_line.size() ? mesh.face_line[f] : 0;
    std::vector<Triangle> pieces;
    if (next_cut < cuts.cut_faces.size() && cuts.cut_faces[next_cut] == f) {
      pieces = arrangement::triangulate_cut_face(mesh, f, cuts.of_cut_face[next_cut++], cuts.points);
    } else {
      pieces = {mesh.triangles[f]};
    }
    for (const Triangle& t : pieces) {
      arranged.add_triangle(t, group, line);
      arranged.face_source.push_back(mesh.source_face(f));
      parent.push_back(f);
    }
  }
  return arranged;
}

// The region each connected piece of space around the arrangement belongs to, given the
// regions of the input faces' sides (see the header).
std::vector<std::int32_t> regions_of_pieces(const SurfaceMesh& arranged, const std::vector<Index>& parent,
                                            const std::vector<RegionPair>& input_regions, std::size_t num_regions,
                                            const std::function<Index(std::size_t)>& piece_of, std::size_t num_pieces) {
  // Winding numbers of every region's boundary, carried from the unbounded piece across faces:
  // crossing a face from its back to its front enters the region its input face has in front
  // and leaves the one it has behind.
  std::vector<std::vector<Index>> faces_of_piece(num_pieces);
  for (Index f = 0; f < arranged.num_faces(); ++f) {
    const Index b = piece_of(back_side(f)), fr = piece_of(front_side(f));
    if (b == fr) continue;
    faces_of_piece[b].push_back(f);
    faces_of_piece[fr].push_back(f);
  }
  std::vector<std::vector<int>> winding(num_pieces);
  winding[0].assign(num_regions, 0);
  winding[0][0] = 1;
  std::deque<Index> queue{0};
  while (!queue.empty()) {
    const Index p = queue.front();
    queue.pop_front();
    for (Index f : faces_of_piece[p]) {
      const RegionPair& given = input_regions[parent[f]];
      const bool forward = piece_of(back_side(f)) == p;
      const Index q = forward ? piece_of(front_side(f)) : piece_of(back_side(f));
      if (!winding[q].empty()) continue;
      winding[q] = winding[p];
      const int step = forward ? 1 : -1;
      winding[q][given.front] += step;
      winding[q][given.back] -= step;
      queue.push_back(q);
    }
  }

  // The area of sides facing each piece, by the region their input face names there.
  std::vector<std::map<std::int32_t, double>> named(num_pieces);
  for (Index f = 0; f < arranged.num_faces(); ++f) {
    const RegionPair& given = input_regions[parent[f]];
    const double a = area(arranged, f);
    named[piece_of(back_side(f))][given.back] += a;
    named[piece_of(front_side(f))][given.front] += a;
  }

  std::vector<std::int32_t> region(num_pieces, 0);
  for (Index p = 1; p < num_pieces; ++p) {
    std::vector<std::int32_t> claimants;
    for (std::size_t r = 0; r < num_regions && !winding[p].empty(); ++r) {
      if (winding[p][r] >= 1) claimants.push_back(static_cast<std::int32_t>(r));
    }
    if (claimants.size() == 1) {
      region[p] = claimants.front();
      continue;
    }
    double best = -1;
    for (const auto& [r, a] : named[p]) {
      const bool eligible = claimants.empty() || std::find(claimants.begin(), claimants.end(), r) != claimants.end();
      if (eligible && a > best) {
        best = a;
        region[p] = r;
      }
    }
    if (best < 0) region[p] = claimants.front();
  }
  return region;
}

}  // namespace

SurfaceMesh resolve_self_intersections(const SurfaceMesh& mesh, SelfIntersectionStats* stats) {
  SelfIntersectionStats counts;
  const std::vector<geometry::FacePair> pairs = geometry::find_self_intersections(mesh);
  counts.face_pairs = pairs.size();
  if (pairs.empty()) {
    counts.faces = mesh.num_faces();
    if (stats) *stats = counts;
    return mesh;
  }
  // The regions as the input states them: shells joined at its edges, nested by ray parity.
  SurfaceMesh labelled = mesh;
  label_regions(labelled);

  const arrangement::FaceCuts cuts = arrangement::find_face_cuts(mesh, pairs);
  counts.faces_cut = cuts.cut_faces.size();
  counts.points_added = cuts.points.size() - mesh.num_vertices();
  std::vector<Index> parent;
  const SurfaceMesh arranged = cut_faces(mesh, cuts, parent);
  if (const auto left = geometry::find_self_intersections(arranged); !left.empty()) {
    const auto [f, g] = left.front();
    throw Error(Error::Kind::InvalidGeometry,
                "cannot resolve the self-intersections: after cutting, pieces of " + describe_face(arranged, f) +
                    " and " + describe_face(arranged, g) + " still cross (" + std::to_string(left.size()) +
                    " pairs), where rounding moved a crossing point",
                {.face = parent[f]});
  }

  const EdgeTopology topology = build_edge_topology(arranged);
  const regions::Shells shells = regions::join_sides(arranged, topology);
  const geometry::RayCaster rays(arranged);
  const regions::ShellRegions pieces = regions::nest_shells(arranged, topology, shells, rays);
  const auto piece_of = [&](std::size_t side) { return pieces.of_shell[shells.of_side[side]]; };
  const std::vector<std::int32_t> region = regions_of_pieces(
      arranged, parent, labelled.face_regions, labelled.region_names.size(), piece_of, pieces.count);

  // Faces with one region on both sides that parted two in the input lie inside that region.
  SurfaceMesh resolved;
  resolved.groups = mesh.groups;
  resolved.region_names = labelled.region_names;
  std::vector<RegionPair> face_regions;
  std::vector<Index> vertex_of(arranged.num_vertices(), static_cast<Index>(-1));
  for (Index f = 0; f < arranged.num_faces(); ++f) {
    const RegionPair sides{region[piece_of(back_side(f))], region[piece_of(front_side(f))]};
    const RegionPair& given = labelled.face_regions[parent[f]];
    if (sides.back == sides.front && given.back != given.front) {
      ++counts.faces_dropped;
      continue;
    }
    Triangle t = arranged.triangles[f];
    for (Index& v : t) {
      if (vertex_of[v] == static_cast<Index>(-1)) {
        vertex_of[v] = static_cast<Index>(resolved.vertices.size());
        resolved.vertices.push_back(arranged.vertices[v]);
      }
      v = vertex_of[v];
    }
    resolved.add_triangle(t, arranged.face_group[f], arranged.face_line[f]);
    resolved.face_source.push_back(arranged.face_source[f]);
    face_regions.push_back(sides);
  }
  resolved.face_regions = std::move(face_regions);
  counts.faces = resolved.num_faces();
  if (stats) *stats = counts;
  return resolved;
}

}  // namespace vorocrust
