// Regions of space (paper section 3, "Non-manifold models"): input step before features (2.2).
#include "vorocrust/regions.hpp"

#include <algorithm>
#include <optional>
#include <string>

#include "geometry/ray_cast.hpp"
#include "regions/nest_shells.hpp"
#include "regions/region_labels_hold.hpp"
#include "regions/shells.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust {

namespace {

using regions::back_side;
using regions::front_side;

Index face_of(std::size_t side) { return static_cast<Index>(side / 2); }

std::int32_t given_label(const SurfaceMesh& mesh, std::size_t side) {
  if (!mesh.has_regions()) return RegionPair::kUnknownRegion;
  const RegionPair& pair = mesh.face_regions[face_of(side)];
  return side % 2 ? pair.front : pair.back;
}

const char* side_name(std::size_t side) { return side % 2 ? "front" : "back"; }

}  // namespace

std::vector<RegionSummary> label_regions(SurfaceMesh& mesh) {
  const EdgeTopology topology = build_edge_topology(mesh);
  const regions::Shells shells = regions::join_sides(mesh, topology);
  const geometry::RayCaster rays(mesh);
  const regions::ShellRegions pieces = regions::nest_shells(mesh, topology, shells, rays);
  const auto piece_of = [&](std::size_t side) { return pieces.of_shell[shells.of_side[side]]; };

  // The label the input gives each piece, and the side that gave it.
  std::vector<std::int32_t> given(pieces.count, RegionPair::kUnknownRegion);
  std::vector<std::size_t> witness(pieces.count, 0);
  for (std::size_t side = 0; side < 2 * mesh.num_faces(); ++side) {
    const std::int32_t label = given_label(mesh, side);
    if (label < 0) continue;
    const Index p = piece_of(side);
    if (given[p] < 0) {
      given[p] = label;
      witness[p] = side;
    } else if (given[p] != label) {
      const std::size_t first = witness[p];
      throw Error(Error::Kind::InvalidGeometry,
                  "the " + std::string(side_name(first)) + " of " + describe_face(mesh, face_of(first)) + " and the " +
                      side_name(side) + " of " + describe_face(mesh, face_of(side)) +
                      " face one region of space, but the first names it " + mesh.region_names[given[p]] +
                      " and the second " + mesh.region_names[label],
                  {.face = face_of(side)});
    }
  }

  // Labels: 0 for the unbounded piece, then by name for named pieces and one each for the rest,
  // in the order of the pieces' first sides.
  std::vector<std::string> names{given[0] >= 0 ? mesh.region_names[given[0]] : "outside"};
  std::vector<std::int32_t> label_of(pieces.count, 0);
  std::vector<Index> unnamed;
  for (Index p = 1; p < pieces.count; ++p) {
    if (given[p] < 0) {
      unnamed.push_back(p);
      label_of[p] = static_cast<std::int32_t>(names.size());
      names.emplace_back();
      continue;
    }
    const std::string& name = mesh.region_names[given[p]];
    const auto it = std::find(names.begin(), names.end(), name);
    label_of[p] = static_cast<std::int32_t>(it - names.begin());
    if (it == names.end()) names.push_back(name);
  }
  const bool labelled = std::any_of(given.begin(), given.end(), [](std::int32_t g) { return g >= 0; });
  for (Index p : unnamed) {
    std::string name = !labelled && unnamed.size() == 1 ? "inside" : "region" + std::to_string(label_of[p]);
    while (std::find(names.begin(), names.end(), name) != names.end()) name += "_";
    names[label_of[p]] = name;
  }

  std::vector<RegionSummary> summary(names.size());
  for (std::size_t r = 0; r < names.size(); ++r) summary[r].name = names[r];
  for (Index p = 0; p < pieces.count; ++p) ++summary[label_of[p]].pieces;
  std::vector<double> six_volume(pieces.count, 0.0);
  const Point origin = mesh.vertices[mesh.triangles.front()[0]];
  mesh.face_regions.resize(mesh.num_faces());
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const double v = (mesh.vertices[t[0]] - origin).dot((mesh.vertices[t[1]] - origin).cross(mesh.vertices[t[2]] - origin));
    const Index back = piece_of(back_side(f)), front = piece_of(front_side(f));
    six_volume[back] += v;
    six_volume[front] -= v;
    mesh.face_regions[f] = RegionPair{label_of[back], label_of[front]};
    ++summary[label_of[back]].sides;
    ++summary[label_of[front]].sides;
  }
  for (Index p = 1; p < pieces.count; ++p) summary[label_of[p]].volume += six_volume[p] / 6;
  mesh.region_names = std::move(names);
  return summary;
}

std::vector<RegionSummary> find_regions(const SurfaceMesh& mesh) {
  SurfaceMesh labelled = mesh;
  return label_regions(labelled);
}

bool region_labels_hold(const SurfaceMesh& mesh) {
  if (!mesh.has_regions() || mesh.region_names.empty()) return true;  // no labels to break
  SurfaceMesh afresh = mesh;
  try {
    label_regions(afresh);
  } catch (const Error& e) {
    if (e.kind() == Error::Kind::InvalidGeometry) return false;
    throw;
  }
  // Labels are numbered by the order label_regions meets the pieces, so they are compared by name.
  const auto name = [](const SurfaceMesh& m, std::int32_t label) -> const std::string* {
    return label >= 0 && static_cast<std::size_t>(label) < m.region_names.size() ? &m.region_names[label] : nullptr;
  };
  const auto same = [&](std::int32_t was, std::int32_t now) {
    const std::string* a = name(mesh, was);
    const std::string* b = name(afresh, now);
    return a && b && *a == *b;
  };
  if (!same(0, 0)) return false;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const RegionPair& a = mesh.face_regions[f];
    const RegionPair& b = afresh.face_regions[f];
    if (!same(a.back, b.back) || !same(a.front, b.front)) return false;
  }
  return true;
}

double materials_volume(const std::vector<RegionSummary>& regions) {
  double volume = 0;
  for (std::size_t label = 1; label < regions.size(); ++label) volume += regions[label].volume;
  return volume;
}

}  // namespace vorocrust
