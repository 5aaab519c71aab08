#include <cstdio>
#include <ostream>

#include "vorocrust/atomic_file.hpp"
#include "vorocrust/balls.hpp"

namespace vorocrust {

const char* to_string(StratumType type) noexcept {
  switch (type) {
    case StratumType::Corner: return "corner";
    case StratumType::Crease: return "crease";
    case StratumType::Patch: return "patch";
  }
  return "?";
}

void write_balls_csv(const std::vector<Ball>& balls, const std::filesystem::path& path) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "x,y,z,radius,stratum_type,stratum_index\n";
    char line[256];
    for (const Ball& b : balls) {
      std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%.17g,%s,%u\n", b.center.x(), b.center.y(), b.center.z(),
                    b.radius, to_string(b.type), b.stratum);
      out << line;
    }
  });
}

void write_balls_vtk(const std::vector<Ball>& balls, const std::filesystem::path& path) {
  write_file_atomically(path, [&](std::ostream& out) {
    char line[128];
    out << "# vtk DataFile Version 3.0\nlibvorocrust balls\nASCII\nDATASET POLYDATA\nPOINTS " << balls.size() << " double\n";
    for (const Ball& b : balls) {
      std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", b.center.x(), b.center.y(), b.center.z());
      out << line;
    }
    out << "VERTICES " << balls.size() << ' ' << 2 * balls.size() << '\n';
    for (std::size_t i = 0; i < balls.size(); ++i) out << "1 " << i << '\n';
    out << "POINT_DATA " << balls.size() << "\nSCALARS radius double 1\nLOOKUP_TABLE default\n";
    for (const Ball& b : balls) {
      std::snprintf(line, sizeof line, "%.17g\n", b.radius);
      out << line;
    }
    out << "SCALARS stratum_type int 1\nLOOKUP_TABLE default\n";
    for (const Ball& b : balls) out << static_cast<int>(b.type) << '\n';
    out << "SCALARS stratum_index int 1\nLOOKUP_TABLE default\n";
    for (const Ball& b : balls) out << b.stratum << '\n';
  });
}

}  // namespace vorocrust
