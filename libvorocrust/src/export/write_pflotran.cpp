#include "vorocrust/write_pflotran.hpp"

#include <map>
#include <string>
#include <vector>

#include "export/region_words.hpp"
#include "export/spill_text.hpp"
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

  // mesh.uge goes out as it is made; the cell list of each material and the boundary connections
  // of each patch, a line per cell or boundary face, are gathered for their own files.
  std::map<std::int32_t, std::string> materials;
  std::map<std::pair<std::int32_t, std::int32_t>, std::pair<std::size_t, std::string>> patches;
  write_file_atomically(folder / "mesh.uge", [&](std::ostream& out) {
    std::string text = "CELLS " + std::to_string(mesh.cells.size()) + "\n";
    for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
      const VoronoiCell& cell = mesh.cells[c];
      io::append_number(text, static_cast<long long>(c + 1));
      append_point(text, cell.site);
      text += ' ';
      io::append_number(text, cell.volume);
      text += '\n';
      io::spill(out, text);
      std::string& list = materials[cell.region];
      io::append_number(list, static_cast<long long>(c + 1));
      list += '\n';
    }
    std::size_t connections = 0;
    for (const VoronoiFace& f : mesh.faces) connections += f.neighbour != kNoCell;
    text += "CONNECTIONS " + std::to_string(connections) + "\n";
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
      io::spill(out, text);
    }
    io::spill(out, text, 0);
  });
  for (const auto& [region, list] : materials) write_file_atomically(folder / (word(region) + ".txt"), list);
  for (const auto& [pair, patch] : patches) {
    write_file_atomically(folder / (word(pair.first) + "_to_" + word(pair.second) + ".ex"),
                          "CONNECTIONS " + std::to_string(patch.first) + "\n" + patch.second);
  }
}

}  // namespace vorocrust
