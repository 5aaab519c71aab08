#include <cstdio>
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
