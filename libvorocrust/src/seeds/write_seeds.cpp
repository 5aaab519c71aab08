#include <cstdio>
#include <iterator>
#include <ostream>

#include "vorocrust/atomic_file.hpp"
#include "vorocrust/seeds.hpp"

namespace vorocrust {

const char* to_string(SeedKind kind) noexcept {
  switch (kind) {
    case SeedKind::Surface: return "surface";
    case SeedKind::Interior: return "interior";
    case SeedKind::Outside: return "outside";
    case SeedKind::Cap: return "cap";
    case SeedKind::Repair: return "repair";
  }
  return "?";
}

namespace {
constexpr SeedKind kKinds[] = {SeedKind::Surface, SeedKind::Interior, SeedKind::Outside, SeedKind::Cap,
                               SeedKind::Repair};
}  // namespace

std::optional<SeedKind> seed_kind_named(std::string_view name) noexcept {
  for (SeedKind kind : kKinds) {
    if (name == to_string(kind)) return kind;
  }
  return std::nullopt;
}

std::string seed_kind_names() {
  std::string names;
  for (std::size_t k = 0; k < std::size(kKinds); ++k) {
    names += k == 0 ? "" : k + 1 == std::size(kKinds) ? " or " : ", ";
    names += to_string(kKinds[k]);
  }
  return names;
}

void write_seeds_csv(const std::vector<Seed>& seeds, const std::filesystem::path& path) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "x,y,z,label,radius,kind\n";
    char line[256];
    for (const Seed& s : seeds) {
      std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%d,%.17g,%s\n", s.position.x(), s.position.y(),
                    s.position.z(), s.region, s.radius, to_string(s.kind));
      out << line;
    }
  });
}

}  // namespace vorocrust
