// vorocrust/mesher.hpp — the whole pipeline, from an input surface to a conforming Voronoi mesh.
//
// Stages (paper sections): features 2.2 -> refinement 2.3 -> seeds 2.4 -> interior 2.5 -> cells.
// generate_mesh runs them on a surface in memory; run_job (job.hpp) also reads, validates and
// writes, as every front end does. Runs are reproducible: equal input, options and seed give
// equal output, whatever the number of threads.
#pragma once

#include "vorocrust/api.hpp"
#include "vorocrust/mesh_result.hpp"
#include "vorocrust/options.hpp"
#include "vorocrust/progress.hpp"
#include "vorocrust/resolve_self_intersections.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

// The surface the pipeline starts from: `input` in its box (options.box, or the default box of an
// input with open sheets), then cut along its self-intersections when options.self_intersections
// is Resolve (`stats`, when given, says what the cutting did). The balls cover this surface (or
// its smoothing), so `check-balls` checks them against it. Throws Error(InvalidGeometry) for a
// vertex outside the box or faces the cutting cannot separate.
VOROCRUST_API SurfaceMesh prepare_domain(const SurfaceMesh& input, const MeshOptions& options, SelfIntersectionStats* stats = nullptr);

// Runs the pipeline up to options.stop_after. Throws Error: Usage for options out of range,
// Cancelled when progress returns false, InvalidGeometry when the input cannot be meshed.
VOROCRUST_API MeshResult generate_mesh(const SurfaceMesh& input, const MeshOptions& options, const ProgressCallback& progress = {});

}  // namespace vorocrust
