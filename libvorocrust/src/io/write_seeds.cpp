#include <iterator>
#include <ostream>
#include <string>

#include "io/text_numbers.hpp"
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

// Numbers by io::append_number, which ignores the locale: printf's would write decimal commas
// in a host application (FreeCAD, MeshLab) that runs in a decimal-comma locale.
void write_seeds_csv(const std::vector<Seed>& seeds, const std::filesystem::path& path) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "x,y,z,label,radius,kind\n";
    std::string line;
    for (const Seed& s : seeds) {
      line.clear();
      for (int k = 0; k < 3; ++k) {
        io::append_number(line, s.position[k]);
        line += ',';
      }
      io::append_number(line, static_cast<long long>(s.region));
      line += ',';
      io::append_number(line, s.radius);
      line += ',';
      line += to_string(s.kind);
      line += '\n';
      out << line;
    }
  });
}

}  // namespace vorocrust
