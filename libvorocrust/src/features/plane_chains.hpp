// Internal: the features of a 2D domain (paper 2.2, 2.6): its corners and the chains of segments
// between them.
//
// A corner is a point where other than two segments meet (a junction, or a segment's free end)
// or where two meet turning by more than the sharp angle. A chain is a polyline of segments from
// corner to corner through points that are not corners; segments in a loop without corners form
// a closed chain starting at its lowest-numbered point.
#pragma once

#include <cstdint>
#include <vector>

#include "vorocrust/plane.hpp"

namespace vorocrust::features {

struct Chain {
  std::vector<Index> points;  // through the domain's points; a closed chain ends where it starts
  std::vector<double> arc;    // length along the chain to each point
  bool loop = false;          // closed, without a corner
  double length() const { return arc.back(); }
};

struct PlaneFeatures {
  std::vector<bool> corner;  // per point
  std::vector<Chain> chains;
  // Per corner, the chains leaving it counter-clockwise by direction: {chain, at its end}.
  std::vector<std::vector<std::pair<std::uint32_t, bool>>> leaving;
};

PlaneFeatures find_plane_features(const PlanarDomain& domain, double sharp_angle_degrees);

// The point at length s along the chain (s clamped to it), and the unit direction there.
Point2 chain_point(const PlanarDomain& domain, const Chain& chain, double s);
Point2 chain_direction(const PlanarDomain& domain, const Chain& chain, double s);

// The direction a chain leaves its start (at_end false) or its end (true) in.
Point2 leaving_direction(const PlanarDomain& domain, const Chain& chain, bool at_end);

}  // namespace vorocrust::features
