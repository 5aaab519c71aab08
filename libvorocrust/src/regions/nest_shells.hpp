// Internal: shells on separate parts of a surface joined into regions of space.
//
// Within one connected part every region it touches presents one shell (shells.hpp); a part's
// *outer* shell is the one seen from far away. A part lies in the region of the innermost
// bounded shell of another part around it (found by the parity of a ray's crossings with that
// shell, the smallest enclosed volume winning), or in the unbounded region when none is around
// it; its outer shell joins that region. The space between two nested spheres thus gets the
// inner side of the outer sphere and the outer side of the inner one.
#pragma once

#include <vector>

#include "core/edge_topology.hpp"
#include "geometry/ray_cast.hpp"
#include "regions/shells.hpp"

namespace vorocrust::regions {

struct ShellRegions {
  std::vector<Index> of_shell;  // region 0 is the unbounded one; others in order of first shell
  std::size_t count = 0;
};

ShellRegions nest_shells(const SurfaceMesh& mesh, const EdgeTopology& topology, const Shells& shells,
                         const geometry::RayCaster& rays);

}  // namespace vorocrust::regions
