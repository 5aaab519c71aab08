// vorocrust/balls.hpp — the protecting and covering balls of the refinement (paper section 2.3).
//
// Every ball is centred on the input surface, on one stratum: a sharp corner, a crease (a chain
// of sharp edges) or a smooth patch. Together the balls cover the surface and satisfy the
// conditions C1-C4 of docs/ball-conditions.md.
#pragma once

#include "vorocrust/api.hpp"

#include <cstdint>
#include <filesystem>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

// Ordered by dimension: corners (0), creases (1), patches (2).
enum class StratumType : std::uint8_t { Corner = 0, Crease = 1, Patch = 2 };

VOROCRUST_API const char* to_string(StratumType type) noexcept;

struct VOROCRUST_API Ball {
  Point center;
  double radius = 0;
  StratumType type = StratumType::Patch;
  Index stratum = 0;  // corner, crease or patch number
};

// OUTDIR/balls.csv: `x,y,z,radius,stratum_type,stratum_index`, 17 significant digits.
VOROCRUST_API void write_balls_csv(const std::vector<Ball>& balls, const std::filesystem::path& path);
// A VTK legacy polydata file of the ball centres with radius, type and stratum as point data,
// viewable in ParaView (glyph by radius to see the balls).
VOROCRUST_API void write_balls_vtk(const std::vector<Ball>& balls, const std::filesystem::path& path);

}  // namespace vorocrust
