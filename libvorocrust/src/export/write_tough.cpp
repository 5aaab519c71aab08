#include "vorocrust/write_tough.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cmath>
#include <set>

#include "export/spill_text.hpp"
#include "io/text_numbers.hpp"
#include "vorocrust/atomic_file.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust {

namespace {

constexpr char kDigitsAndLetters[] = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ";
constexpr std::size_t kMaxCells = 26u * 36u * 36u * 100u;

std::string padded(std::string text, std::size_t width) {
  text.resize(width, ' ');
  return text;
}

}  // namespace

std::string tough_element_name(std::size_t cell) {
  if (cell >= kMaxCells) {
    throw Error(Error::Kind::Output, "a TOUGH MESH file names at most " + std::to_string(kMaxCells) + " cells");
  }
  const std::size_t code = cell / 100, number = cell % 100;
  std::string name(5, ' ');
  name[0] = static_cast<char>('A' + code / (36 * 36));
  name[1] = kDigitsAndLetters[code / 36 % 36];
  name[2] = kDigitsAndLetters[code % 36];
  if (number >= 10) name[3] = static_cast<char>('0' + number / 10);
  name[4] = static_cast<char>('0' + number % 10);
  return name;
}

std::map<std::int32_t, std::string> tough_material_names(const VoronoiMesh& mesh) {
  std::set<std::int32_t> materials;
  for (const VoronoiCell& c : mesh.cells) materials.insert(c.region);
  std::map<std::int32_t, std::string> names;
  std::set<std::string> taken;
  for (std::int32_t label : materials) {
    std::string name;
    for (unsigned char c : region_name(mesh, label)) {
      if (std::isalnum(c) || c == '_') name += static_cast<char>(c);
    }
    if (name.size() > 5) {  // "region12" -> "reg12": a prefix, and the label telling it apart
      const std::string digits = std::to_string(label);
      name = name.substr(0, 5 - std::min<std::size_t>(digits.size(), 5)) + digits;
    }
    if (name.empty() || taken.count(name)) {
      char fallback[16];
      std::snprintf(fallback, sizeof fallback, label <= 99 ? "MAT%02d" : "M%04d", label);
      name = fallback;
    }
    taken.insert(name);
    names[label] = name;
  }
  return names;
}

void write_tough_mesh(const VoronoiMesh& mesh, const std::filesystem::path& path) {
  if (mesh.cells.size() > kMaxCells) tough_element_name(mesh.cells.size());  // throws
  const std::map<std::int32_t, std::string> material = tough_material_names(mesh);
  write_file_atomically(path, [&](std::ostream& out) {
    std::string text = "ELEME\n";
    const std::string blank5(5, ' '), blank10(10, ' ');
    for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
      const VoronoiCell& cell = mesh.cells[c];
      text += tough_element_name(c) + blank5 + blank5 + padded(material.at(cell.region), 5);
      text += io::fortran_e(cell.volume, 10) + blank10 + blank10;
      for (int k = 0; k < 3; ++k) text += io::fortran_e(cell.site[k], 10);
      text += '\n';
      io::spill(out, text);
    }
    text += "\nCONNE\n";
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
      const VoronoiFace& face = mesh.faces[f];
      if (face.neighbour == kNoCell) continue;
      const Point link = mesh.cells[face.neighbour].site - mesh.cells[face.owner].site;
      const double length = link.norm();
      int axis = 0;
      link.cwiseAbs().maxCoeff(&axis);
      text += tough_element_name(face.owner) + tough_element_name(face.neighbour) + blank5 + blank5 + blank5;
      text += "    " + std::to_string(axis + 1);
      text += io::fortran_e(length / 2, 10) + io::fortran_e(length / 2, 10);
      text += io::fortran_e(face_geometry(mesh, f).area, 10) + io::fortran_e(-link.z() / length, 10);
      text += '\n';
      io::spill(out, text);
    }
    text += "\n";
    io::spill(out, text, 0);
  });
}

}  // namespace vorocrust
