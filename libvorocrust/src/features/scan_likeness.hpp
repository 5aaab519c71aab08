// features/scan_likeness.hpp — does a surface look like a scan, or a tessellation of a curved shape,
// to the sharp-edge rule (paper 2.2)?
//
// The paper's rule makes an edge sharp when its faces bend by more than theta#. On a CAD part the
// sharp edges are its true creases: bent far past theta# (90 degrees on most), in long chains. On a
// scan, or a coarse tessellation of a curved shape, they are folds of the tessellation: bent just
// past theta#, scattered in many short chains, which then mesh as a crowd of tiny creases and
// corners (a femur scan: 1.09 million cells, worst surface triangle 0.004). Such a surface should
// be meshed as smooth (option `smooth`), or at a larger sharp angle.
//
// sharp_bends(mesh, theta#) measures the edges with two faces bent past theta# (radians): how many,
// how many bend less than kNearBend past it, and the connected chains they form. The surface
// looks like a scan when at least kMinChains such chains hold most of those edges near theta#,
// and the median chain has at most kShortChain edges. Measured on the shared models and on
// CGAL's data meshes (150 models), no CAD part meets this (fandisk_large: 39 % near, in 9 chains;
// a turbine: 30 %, median chain 19 edges), and every scan with more than a handful of sharp
// edges does (femur: 3 934 sharp edges, 34 % near, 109 chains of median 2 edges).
#pragma once

#include <cstddef>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::features {

struct SharpBends {
  static constexpr double kNearBend = 15.0 * 3.14159265358979323846 / 180;  // radians past theta#
  static constexpr double kNearShare = 0.3;
  static constexpr std::size_t kMinChains = 20;
  static constexpr std::size_t kShortChain = 5;

  std::size_t sharp_edges = 0;     // edges of two faces bent past theta#
  std::size_t near_sharp_angle = 0;  // of them, bent by less than theta# + kNearBend
  std::size_t chains = 0;            // connected sets of those edges
  std::size_t median_chain = 0;      // edges in the median chain

  bool looks_like_scan() const {
    return chains >= kMinChains && static_cast<double>(near_sharp_angle) >= kNearShare * static_cast<double>(sharp_edges) &&
           median_chain <= kShortChain;
  }
};

SharpBends sharp_bends(const SurfaceMesh& mesh, double sharp_angle);

}  // namespace vorocrust::features
