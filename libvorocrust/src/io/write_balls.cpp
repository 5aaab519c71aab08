#include <ostream>
#include <string>

#include "io/text_numbers.hpp"
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

// Numbers by io::append_number, which ignores the locale (printf's follows the host's).
void write_balls_csv(const std::vector<Ball>& balls, const std::filesystem::path& path) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "x,y,z,radius,stratum_type,stratum_index\n";
    std::string line;
    for (const Ball& b : balls) {
      line.clear();
      for (double x : {b.center.x(), b.center.y(), b.center.z(), b.radius}) {
        io::append_number(line, x);
        line += ',';
      }
      line += to_string(b.type);
      line += ',';
      io::append_number(line, static_cast<long long>(b.stratum));
      line += '\n';
      out << line;
    }
  });
}

void write_balls_vtk(const std::vector<Ball>& balls, const std::filesystem::path& path) {
  write_file_atomically(path, [&](std::ostream& out) {
    std::string line;
    out << "# vtk DataFile Version 3.0\nlibvorocrust balls\nASCII\nDATASET POLYDATA\nPOINTS " << balls.size() << " double\n";
    for (const Ball& b : balls) {
      line.clear();
      for (int k = 0; k < 3; ++k) {
        io::append_number(line, b.center[k]);
        line += k < 2 ? ' ' : '\n';
      }
      out << line;
    }
    out << "VERTICES " << balls.size() << ' ' << 2 * balls.size() << '\n';
    for (std::size_t i = 0; i < balls.size(); ++i) out << "1 " << i << '\n';
    out << "POINT_DATA " << balls.size() << "\nSCALARS radius double 1\nLOOKUP_TABLE default\n";
    for (const Ball& b : balls) {
      line.clear();
      io::append_number(line, b.radius);
      line += '\n';
      out << line;
    }
    out << "SCALARS stratum_type int 1\nLOOKUP_TABLE default\n";
    for (const Ball& b : balls) out << static_cast<int>(b.type) << '\n';
    out << "SCALARS stratum_index int 1\nLOOKUP_TABLE default\n";
    for (const Ball& b : balls) out << b.stratum << '\n';
  });
}

}  // namespace vorocrust
