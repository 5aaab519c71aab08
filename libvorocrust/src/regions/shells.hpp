// Internal: face sides joined into shells (paper section 3, "Non-manifold models").
//
// Every face has two sides: its back, side 2f, and its front, side 2f + 1, the side its normal
// points to. Two sides face the same region of space when they bound one wedge around an edge
// (see radial_order.hpp); a boundary edge joins the two sides of its one face. The classes of
// sides so joined are shells: each is the whole boundary that one region of space presents to
// one connected part of the surface. A region enclosed by several separate parts (the space
// between two nested spheres) has one shell on each, and nest_shells() joins them.
#pragma once

#include <vector>

#include "core/edge_topology.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::regions {

inline std::size_t back_side(Index f) { return 2 * std::size_t{f}; }
inline std::size_t front_side(Index f) { return 2 * std::size_t{f} + 1; }

struct Shells {
  std::vector<Index> of_side;  // the shell of each side, numbered in order of their first side
  std::size_t count = 0;
};

Shells join_sides(const SurfaceMesh& mesh, const EdgeTopology& topology);

// The signed volume a shell's sides enclose, each side looking into its region: positive for
// the shell that bounds a region from outside, negative for the outer shell of a part (seen
// from the unbounded side). Indexed by shell.
std::vector<double> shell_volumes(const SurfaceMesh& mesh, const Shells& shells);

}  // namespace vorocrust::regions
