// vorocrust/mesher.hpp — the whole pipeline, from an input surface to a conforming Voronoi mesh.
//
// Stages (paper sections): features 2.2 -> refinement 2.3 -> seeds 2.4 -> interior 2.5 -> cells.
// Every front end (CLI, Python, MeshLab, FreeCAD) calls generate_mesh() with the same options.
// Runs are reproducible: equal input, options and seed give equal output.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "vorocrust/progress.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

struct MeshOptions {
  double lipschitz = 0.25;             // L < 1: how fast ball radii may vary
  double sharp_angle_degrees = 30.0;   // theta#: dihedral deviation that makes an edge sharp
  double max_size = std::numeric_limits<double>::infinity();  // uniform sizing bound
  std::uint64_t seed = 0;              // random seed; equal seeds give equal meshes
  int threads = 0;                     // 0 = all hardware threads

  // Throws Error(Usage) naming the first option out of its range.
  void check() const;
};

struct PhaseTiming {
  std::string name;
  double seconds = 0;
};

struct MeshResult {
  std::vector<PhaseTiming> timings;
};

// Not yet available: throws Error(NotImplemented) after checking the options.
MeshResult generate_mesh(const SurfaceMesh& input, const MeshOptions& options, const ProgressCallback& progress = {});

}  // namespace vorocrust
