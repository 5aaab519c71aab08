#include "vorocrust/write_openfoam.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <numeric>
#include <string>
#include <system_error>
#include <vector>

#include "export/region_words.hpp"
#include "export/spill_text.hpp"
#include "io/text_numbers.hpp"
#include "vorocrust/atomic_file.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust {
namespace {

namespace fs = std::filesystem;

std::string header(const char* cls, const char* location, const char* object, const std::string& note = "") {
  std::string h = "FoamFile\n{\n    version     2.0;\n    format      ascii;\n    class       ";
  h += cls;
  h += ";\n";
  if (!note.empty()) h += "    note        \"" + note + "\";\n";
  h += "    location    \"";
  h += location;
  h += "\";\n    object      ";
  h += object;
  h += ";\n}\n\n";
  return h;
}

struct Patch {
  std::string name;
  std::size_t start = 0, size = 0;
  bool empty = false;  // the front and back of an extruded 2D mesh
};

// Faces in OpenFOAM's order, and the patches of the boundary ones.
struct Ordering {
  std::vector<std::size_t> faces;
  std::size_t internal = 0;
  std::vector<Patch> patches;
};

Ordering order_faces(const VoronoiMesh& mesh, const io::RegionWords& word) {
  Ordering o;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    if (mesh.faces[f].neighbour != kNoCell) o.faces.push_back(f);
  }
  std::sort(o.faces.begin(), o.faces.end(), [&](std::size_t a, std::size_t b) {
    const VoronoiFace &fa = mesh.faces[a], &fb = mesh.faces[b];
    return std::tie(fa.owner, fa.neighbour) < std::tie(fb.owner, fb.neighbour);
  });
  o.internal = o.faces.size();
  std::map<std::pair<std::int32_t, std::int32_t>, std::vector<std::size_t>> by_pair;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const VoronoiFace& face = mesh.faces[f];
    if (face.neighbour == kNoCell) by_pair[{face.regions.back, face.regions.front}].push_back(f);
  }
  for (const auto& [pair, faces] : by_pair) {
    o.patches.push_back({word(pair.first) + "_to_" + word(pair.second), o.faces.size(), faces.size(),
                         pair.second == mesh.empty_region});
    o.faces.insert(o.faces.end(), faces.begin(), faces.end());
  }
  return o;
}

// Appends formatted text, for the big lists.
template <class... Args>
void append(std::string& out, const char* format, Args... args) {
  char buffer[128];
  const int n = std::snprintf(buffer, sizeof buffer, format, args...);
  out.append(buffer, static_cast<std::size_t>(n));
}

void write_lists(const VoronoiMesh& mesh, const Ordering& o, const fs::path& poly) {
  const std::string note = "nPoints:" + std::to_string(mesh.points.size()) + "  nCells:" + std::to_string(mesh.cells.size()) +
                           "  nFaces:" + std::to_string(o.faces.size()) + "  nInternalFaces:" + std::to_string(o.internal);
  write_file_atomically(poly / "points", [&](std::ostream& out) {
    std::string text = header("vectorField", "constant/polyMesh", "points");
    append(text, "%zu\n(\n", mesh.points.size());
    // Coordinates by io::append_number: printf's %g would follow a host's decimal-comma locale.
    for (const Point& p : mesh.points) {
      text += '(';
      for (int k = 0; k < 3; ++k) {
        io::append_number(text, p[k]);
        text += k < 2 ? ' ' : ')';
      }
      text += '\n';
      io::spill(out, text);
    }
    text += ")\n";
    io::spill(out, text, 0);
  });
  write_file_atomically(poly / "faces", [&](std::ostream& out) {
    std::string text = header("faceList", "constant/polyMesh", "faces");
    append(text, "%zu\n(\n", o.faces.size());
    for (std::size_t f : o.faces) {
      const std::vector<Index>& polygon = mesh.faces[f].points;
      io::append_number(text, static_cast<long long>(polygon.size()));
      for (std::size_t k = 0; k < polygon.size(); ++k) {
        text += k ? ' ' : '(';
        io::append_number(text, static_cast<long long>(polygon[k]));
      }
      text += ")\n";
      io::spill(out, text);
    }
    text += ")\n";
    io::spill(out, text, 0);
  });
  // A label a line: the owner of every face, the neighbour of the first o.internal.
  const auto write_labels = [&](const char* name, const std::string& note, std::size_t count, auto label) {
    write_file_atomically(poly / name, [&](std::ostream& out) {
      std::string text = header("labelList", "constant/polyMesh", name, note);
      append(text, "%zu\n(\n", count);
      for (std::size_t k = 0; k < count; ++k) {
        io::append_number(text, static_cast<long long>(label(mesh.faces[o.faces[k]])));
        text += '\n';
        io::spill(out, text);
      }
      text += ")\n";
      io::spill(out, text, 0);
    });
  };
  write_labels("owner", note, o.faces.size(), [](const VoronoiFace& f) { return f.owner; });
  write_labels("neighbour", note, o.internal, [](const VoronoiFace& f) { return f.neighbour; });
}

// An OpenFOAM labelList, `name List<label>` with its count and one entry a line.
template <class Items, class Item>
void append_list(std::string& text, const char* name, const char* type, const Items& items, Item item) {
  text += std::string("    ") + name + " List<" + type + ">\n";
  append(text, "%zu\n(\n", items.size());
  for (const auto& x : items) {
    io::append_number(text, static_cast<long long>(item(x)));
    text += '\n';
  }
  text += ")\n;\n";
}

void write_boundary_and_zones(const VoronoiMesh& mesh, const Ordering& o, const io::RegionWords& word,
                              const fs::path& poly) {
  std::string text = header("polyBoundaryMesh", "constant/polyMesh", "boundary");
  append(text, "%zu\n(\n", o.patches.size());
  for (const Patch& p : o.patches) {
    text += "    " + p.name + "\n    {\n        type            " + (p.empty ? "empty" : "patch") + ";\n";
    append(text, "        nFaces          %zu;\n        startFace       %zu;\n    }\n", p.size, p.start);
  }
  text += ")\n";
  write_file_atomically(poly / "boundary", text);

  std::map<std::int32_t, std::vector<std::size_t>> zones;
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) zones[mesh.cells[c].region].push_back(c);
  text = header("regIOobject", "constant/polyMesh", "cellZones");
  append(text, "%zu\n(\n", zones.size());
  for (const auto& [region, cells] : zones) {
    text += word(region) + "\n{\n    type cellZone;\n";
    append_list(text, "cellLabels", "label", cells, [](std::size_t c) { return c; });
    text += "}\n";
  }
  text += ")\n";
  write_file_atomically(poly / "cellZones", text);

  // Interfaces between materials are internal faces; each pair of materials is a face zone,
  // oriented from the lower label to the higher (flipMap marks faces whose owner is the higher).
  std::map<std::pair<std::int32_t, std::int32_t>, std::vector<std::size_t>> interfaces;
  for (std::size_t k = 0; k < o.internal; ++k) {
    const VoronoiFace& f = mesh.faces[o.faces[k]];
    if (f.regions.back != f.regions.front) {
      interfaces[{std::min(f.regions.back, f.regions.front), std::max(f.regions.back, f.regions.front)}].push_back(k);
    }
  }
  text = header("regIOobject", "constant/polyMesh", "faceZones");
  append(text, "%zu\n(\n", interfaces.size());
  for (const auto& [pair, faces] : interfaces) {
    text += word(pair.first) + "_to_" + word(pair.second) + "\n{\n    type faceZone;\n";
    append_list(text, "faceLabels", "label", faces, [](std::size_t k) { return k; });
    append_list(text, "flipMap", "bool", faces,
                [&, low = pair.first](std::size_t k) { return mesh.faces[o.faces[k]].regions.back != low; });
    text += "}\n";
  }
  text += ")\n";
  write_file_atomically(poly / "faceZones", text);
}

// The least a case needs for OpenFOAM's utilities (checkMesh, foamToVTK, the solvers' setup).
void write_system(const fs::path& system) {
  write_file_atomically(system / "controlDict",
                        header("dictionary", "system", "controlDict") +
                            "application     laplacianFoam;\nstartFrom       startTime;\nstartTime       0;\n"
                            "stopAt          endTime;\nendTime         1;\ndeltaT          1;\n"
                            "writeControl    timeStep;\nwriteInterval   1;\npurgeWrite      0;\n"
                            "writeFormat     ascii;\nwritePrecision  17;\nwriteCompression off;\n"
                            "timeFormat      general;\ntimePrecision   6;\nrunTimeModifiable false;\n");
  write_file_atomically(system / "fvSchemes",
                        header("dictionary", "system", "fvSchemes") +
                            "ddtSchemes\n{\n    default         steadyState;\n}\n"
                            "gradSchemes\n{\n    default         Gauss linear;\n}\n"
                            "divSchemes\n{\n    default         none;\n}\n"
                            "laplacianSchemes\n{\n    default         Gauss linear corrected;\n}\n"
                            "interpolationSchemes\n{\n    default         linear;\n}\n"
                            "snGradSchemes\n{\n    default         corrected;\n}\n");
  write_file_atomically(system / "fvSolution", header("dictionary", "system", "fvSolution") +
                                                   "solvers\n{\n}\n\nSIMPLE\n{\n    nNonOrthogonalCorrectors 0;\n}\n");
}

void make_folder(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw Error(Error::Kind::Output, "cannot create the folder: " + ec.message(), {.file = dir.string()});
}

}  // namespace

void write_openfoam_case(const VoronoiMesh& mesh, const std::filesystem::path& case_dir) {
  const fs::path poly = case_dir / "constant" / "polyMesh", system = case_dir / "system";
  make_folder(poly);
  make_folder(system);
  const io::RegionWords word(mesh);
  const Ordering o = order_faces(mesh, word);
  write_lists(mesh, o, poly);
  write_boundary_and_zones(mesh, o, word, poly);
  write_system(system);
}

}  // namespace vorocrust
