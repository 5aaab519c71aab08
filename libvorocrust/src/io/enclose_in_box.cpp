// The box around open sheets (paper section 3, Figure 17).
#include "io/enclose_in_box.hpp"

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "core/edge_topology.hpp"
#include "core/surface_measures.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust {

namespace {

constexpr const char* kBoxGroup = "box";

geometry::Box bounds_of(const SurfaceMesh& input) {
  geometry::Box box;
  for (const Point& p : input.vertices) box.include(p);
  return box;
}

}  // namespace

bool needs_box(const SurfaceMesh& input) {
  const EdgeTopology topology = build_edge_topology(input);
  for (std::size_t e = 0; e < topology.num_edges(); ++e) {
    if (topology.is_boundary(e)) return true;
  }
  return false;
}

bool holds_its_box(const SurfaceMesh& input) {
  if (input.vertices.empty()) return false;
  const geometry::Box bounds = bounds_of(input);
  const Point size = bounds.hi - bounds.lo;
  // The faces flat on each side of the bounding box, whose area must be the side's own.
  std::array<std::vector<Index>, 6> flat;
  for (Index f = 0; f < input.num_faces(); ++f) {
    const Triangle& t = input.triangles[f];
    for (int k = 0; k < 3; ++k) {
      for (int side = 0; side < 2; ++side) {
        const double plane = side ? bounds.hi[k] : bounds.lo[k];
        const auto on = [&](Index v) { return input.vertices[v][k] == plane; };
        if (on(t[0]) && on(t[1]) && on(t[2])) flat[2 * k + side].push_back(f);
      }
    }
  }
  for (int k = 0; k < 3; ++k) {
    const double area = size[(k + 1) % 3] * size[(k + 2) % 3];
    if (!(area > 0)) return false;
    for (int side = 0; side < 2; ++side) {
      if (std::abs(surface_area(input, flat[2 * k + side]) - area) > 1e-9 * area) return false;
    }
  }
  return true;
}

geometry::Box default_box(const SurfaceMesh& input) {
  geometry::Box box = bounds_of(input);
  const Point margin = Point::Constant(0.1 * (box.hi - box.lo).norm());
  box.lo -= margin;
  box.hi += margin;
  return box;
}

SurfaceMesh enclose_in_box(const SurfaceMesh& input, const geometry::Box& box) {
  if (!((box.lo.array() < box.hi.array()).all())) {
    throw Error(Error::Kind::Usage, "--box: the lower corner " + describe_point(box.lo) +
                                        " must lie below the upper corner " + describe_point(box.hi) + " in x, y and z");
  }
  for (std::size_t v = 0; v < input.vertices.size(); ++v) {
    const Point& p = input.vertices[v];
    if (!((box.lo.array() < p.array()).all() && (p.array() < box.hi.array()).all())) {
      throw Error(Error::Kind::InvalidGeometry,
                  "vertex " + std::to_string(v) + " at " + describe_point(p) + " does not lie inside the box " +
                      describe_point(box.lo) + " .. " + describe_point(box.hi) + ": the box must hold the whole model");
    }
  }
  SurfaceMesh out = input;
  // Region 0 inside the box is the domain.
  std::int32_t domain = 0;
  if (out.has_regions()) {
    out.region_names.push_back("domain");
    domain = static_cast<std::int32_t>(out.region_names.size() - 1);
    for (RegionPair& pair : out.face_regions) {
      if (pair.back == 0) pair.back = domain;
      if (pair.front == 0) pair.front = domain;
    }
  } else {
    // The model's own sides are left for the region stage to read: a sheet has the domain on
    // both sides, a closed solid inside the box a region of its own.
    out.region_names = {"outside", "domain"};
    domain = 1;
    out.face_regions.assign(out.triangles.size(), RegionPair{});
  }

  const Index first = static_cast<Index>(out.vertices.size());
  for (int corner = 0; corner < 8; ++corner) {
    out.vertices.emplace_back(corner & 1 ? box.hi.x() : box.lo.x(), corner & 2 ? box.hi.y() : box.lo.y(),
                              corner & 4 ? box.hi.z() : box.lo.z());
  }
  const Index group = static_cast<Index>(out.groups.size());
  out.groups.push_back({kBoxGroup, ""});
  // Each side as a quad of corner bits, counter-clockwise seen from outside.
  static constexpr int kSides[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& side : kSides) {
    for (const Triangle& t : {Triangle{first + side[0], first + side[1], first + side[2]},
                              Triangle{first + side[0], first + side[2], first + side[3]}}) {
      out.add_triangle(t, group);
      out.face_regions.back() = RegionPair{domain, 0};
    }
  }
  return out;
}

std::vector<bool> box_faces(const SurfaceMesh& mesh) {
  std::vector<bool> in_box(mesh.num_faces(), false);
  for (Index f = 0; f < mesh.num_faces() && f < mesh.face_group.size(); ++f) {
    if (mesh.face_group[f] >= mesh.groups.size()) continue;
    const FaceGroup& group = mesh.groups[mesh.face_group[f]];
    in_box[f] = group.name == kBoxGroup && group.source_file.empty();
  }
  return in_box;
}

}  // namespace vorocrust
