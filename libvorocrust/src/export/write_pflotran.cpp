#include "vorocrust/write_pflotran.hpp"

#include <map>
#include <string>
#include <vector>

#include "export/region_words.hpp"
#include "io/text_numbers.hpp"
#include "vorocrust/atomic_file.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust {

namespace {

void append_point(std::string& text, const Point& p) {
  for (int k = 0; k < 3; ++k) {
    text += ' ';
    io::append_number(text, p[k]);
  }
}

}  // namespace

void write_pflotran(const VoronoiMesh& mesh, const std::filesystem::path& folder) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) throw Error(Error::Kind::Output, "cannot create the folder: " + ec.message(), {.file = folder.string()});
  const io::RegionWords word(mesh);

  std::string text = "CELLS " + std::to_string(mesh.cells.size()) + "\n";
  std::map<std::int32_t, std::string> materials;
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    const VoronoiCell& cell = mesh.cells[c];
    io::append_number(text, static_cast<long long>(c + 1));
    append_point(text, cell.site);
    text += ' ';
    io::append_number(text, cell.volume);
    text += '\n';
    std::string& list = materials[cell.region];
    io::append_number(list, static_cast<long long>(c + 1));
    list += '\n';
  }
  std::size_t connections = 0;
  for (const VoronoiFace& f : mesh.faces) connections += f.neighbour != kNoCell;
  text += "CONNECTIONS " + std::to_string(connections) + "\n";
  std::map<std::pair<std::int32_t, std::int32_t>, std::pair<std::size_t, std::string>> patches;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const VoronoiFace& face = mesh.faces[f];
    const FaceGeometry g = face_geometry(mesh, f);
    std::string* line = &text;
    if (face.neighbour == kNoCell) {
      if (face.regions.front == mesh.empty_region) continue;  // a 2D slab's front and back: no flow
      auto& [count, list] = patches[{face.regions.back, face.regions.front}];
      ++count;
      line = &list;
    }
    io::append_number(*line, static_cast<long long>(face.owner + 1));
    if (face.neighbour != kNoCell) {
      *line += ' ';
      io::append_number(*line, static_cast<long long>(face.neighbour + 1));
    }
    append_point(*line, g.centroid);
    *line += ' ';
    io::append_number(*line, g.area);
    *line += '\n';
  }
  write_file_atomically(folder / "mesh.uge", text);
  for (const auto& [region, list] : materials) write_file_atomically(folder / (word(region) + ".txt"), list);
  for (const auto& [pair, patch] : patches) {
    write_file_atomically(folder / (word(pair.first) + "_to_" + word(pair.second) + ".ex"),
                          "CONNECTIONS " + std::to_string(patch.first) + "\n" + patch.second);
  }
}

}  // namespace vorocrust
