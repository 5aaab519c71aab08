// vorocrust/seeds.hpp — the Voronoi seeds (paper sections 2.4 and 2.5).
//
// Surface seeds sit where the bounding spheres of three overlapping balls meet, one on each side
// of the surface, and carry the region (material) of the side they lie on. Their Voronoi facets
// between seeds of different regions form the output surface. Seeds and their labels are the
// whole mesh in compact form: the Voronoi cells follow from them.
#pragma once

#include "vorocrust/api.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

// Surface: a seed of a pair across the surface (paper 2.4). Interior, Outside: a seed away from
// the surface (2.5) in a material or outside. Cap: a seed on one protecting ball's sphere that
// keeps the cells about the ball's centre well shaped (interior/cap_seeds.hpp). Repair: a seed
// placed, off the spheres, to split a cell about a highly skew face; like caps, it is placed
// rather than sampled, so the sampler's rules (clearance, Lipschitz radii) do not bind it.
enum class SeedKind : std::uint8_t { Surface, Interior, Outside, Cap, Repair };

VOROCRUST_API const char* to_string(SeedKind kind) noexcept;
// The kind to_string names `name`, if any.
VOROCRUST_API std::optional<SeedKind> seed_kind_named(std::string_view name) noexcept;
// Every kind's name, for messages: "surface, interior, outside, cap or repair".
VOROCRUST_API std::string seed_kind_names();

// Regions when the input names none: its closed shells bound one material.
inline constexpr std::int32_t kOutsideRegion = 0;
inline constexpr std::int32_t kInsideRegion = 1;

struct VOROCRUST_API Seed {
  Point position;
  std::int32_t region = kOutsideRegion;
  double radius = 0;  // surface seeds: the mean radius of their three balls
  SeedKind kind = SeedKind::Surface;
};

// OUTDIR/seeds.csv: `x,y,z,label,radius,kind` (kind as to_string names it), 17 significant
// digits, written atomically.
VOROCRUST_API void write_seeds_csv(const std::vector<Seed>& seeds, const std::filesystem::path& path);

// Reads what write_seeds_csv writes: the header line `x,y,z,label,radius,kind`, then one seed a
// line (blank lines skipped). Throws Error(UnreadableInput) naming the file and line of the
// first bad line: a missing or wrong header, a field count other than six, a number that does
// not parse or is not finite, a label out of the 32-bit range, a kind to_string names none of.
VOROCRUST_API std::vector<Seed> read_seeds_csv(const std::filesystem::path& path);

}  // namespace vorocrust
