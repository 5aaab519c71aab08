// Internal: surface_topology() from an edge topology the caller already built.
#pragma once

#include "core/edge_topology.hpp"
#include "vorocrust/quality.hpp"

namespace vorocrust {

SurfaceTopology surface_topology(const SurfaceMesh& mesh, const EdgeTopology& topology);

}  // namespace vorocrust
