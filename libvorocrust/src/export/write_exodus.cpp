#include <exodusII.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "export/region_words.hpp"
#include "io/exodus_file.hpp"
#include "vorocrust/atomic_file.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/exodus.hpp"

namespace vorocrust {

namespace {

using io::ExodusFile;

// The cells of each material, in cell order, and each cell's element number (from 1) once the
// blocks are laid out one after the other in label order.
struct Blocks {
  std::map<std::int32_t, std::vector<std::size_t>> cells;
  std::vector<int> element_of_cell;
};

Blocks lay_out_blocks(const VoronoiMesh& mesh) {
  Blocks b;
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) b.cells[mesh.cells[c].region].push_back(c);
  b.element_of_cell.resize(mesh.cells.size());
  int element = 0;
  for (const auto& [label, cells] : b.cells) {
    if (label <= 0) {
      throw Error(Error::Kind::Output, "an Exodus block id must be positive, and material " + std::to_string(label) +
                                           " is not: give the materials positive labels");
    }
    for (std::size_t c : cells) b.element_of_cell[c] = ++element;
  }
  return b;
}

// A side set: the regions on its two sides, and its sides as (element, face position from 1).
struct SideSet {
  std::int32_t from = 0, to = 0;
  std::vector<int> elements, sides;
};

// Boundary patches by (owner's region, region across) and interfaces by (lower, higher) label,
// each side from the cell on the `from` region's side.
std::vector<SideSet> side_sets(const VoronoiMesh& mesh, const Blocks& blocks) {
  std::map<std::pair<std::int32_t, std::int32_t>, SideSet> sets;
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    const VoronoiCell& cell = mesh.cells[c];
    for (std::size_t k = 0; k < cell.faces.size(); ++k) {
      const VoronoiFace& face = mesh.faces[cell.faces[k]];
      const bool boundary = face.neighbour == kNoCell;
      const std::int32_t other = face.owner == static_cast<std::int32_t>(c) ? face.neighbour : face.owner;
      const std::int32_t across = boundary ? face.regions.front : mesh.cells[static_cast<std::size_t>(other)].region;
      if (!boundary && across <= cell.region) continue;  // inside a material, or listed from the other side
      SideSet& set = sets[{cell.region, across}];
      set.from = cell.region;
      set.to = across;
      set.elements.push_back(blocks.element_of_cell[c]);
      set.sides.push_back(static_cast<int>(k + 1));
    }
  }
  std::vector<SideSet> out;
  for (auto& [pair, set] : sets) out.push_back(std::move(set));
  return out;
}

void write_nodes(ExodusFile& file, const VoronoiMesh& mesh) {
  std::vector<double> xyz[3];
  for (int k = 0; k < 3; ++k) {
    xyz[k].reserve(mesh.points.size());
    for (const Point& p : mesh.points) xyz[k].push_back(p[k]);
  }
  file.check(ex_put_coord(file.id(), xyz[0].data(), xyz[1].data(), xyz[2].data()), "the nodes");
  const char* names[3] = {"x", "y", "z"};
  file.check(ex_put_coord_names(file.id(), const_cast<char**>(names)), "the coordinate names");
}

void write_face_block(ExodusFile& file, const VoronoiMesh& mesh) {
  std::vector<int> nodes, counts;
  counts.reserve(mesh.faces.size());
  for (const VoronoiFace& f : mesh.faces) {
    counts.push_back(static_cast<int>(f.points.size()));
    for (Index p : f.points) nodes.push_back(static_cast<int>(p + 1));
  }
  file.check(ex_put_block(file.id(), EX_FACE_BLOCK, ExodusFile::kFaceBlock, "NSIDED",
                          static_cast<int64_t>(mesh.faces.size()), static_cast<int64_t>(nodes.size()), 0, 0, 0),
             "the face block");
  file.check(ex_put_conn(file.id(), EX_FACE_BLOCK, ExodusFile::kFaceBlock, nodes.data(), nullptr, nullptr),
             "the faces' nodes");
  file.check(ex_put_entity_count_per_polyhedra(file.id(), EX_FACE_BLOCK, ExodusFile::kFaceBlock, counts.data()),
             "the faces' sizes");
  file.check(ex_put_name(file.id(), EX_FACE_BLOCK, ExodusFile::kFaceBlock, "faces"), "the face block's name");
}

void write_element_blocks(ExodusFile& file, const VoronoiMesh& mesh, const Blocks& blocks,
                          const io::RegionWords& word) {
  for (const auto& [label, cells] : blocks.cells) {
    std::vector<int> faces, counts;
    for (std::size_t c : cells) {
      counts.push_back(static_cast<int>(mesh.cells[c].faces.size()));
      for (Index f : mesh.cells[c].faces) faces.push_back(static_cast<int>(f + 1));
    }
    const std::string what = "material " + word(label);
    file.check(ex_put_block(file.id(), EX_ELEM_BLOCK, label, "NFACED", static_cast<int64_t>(cells.size()), 0, 0,
                            static_cast<int64_t>(faces.size()), 0),
               "the block of " + what);
    file.check(ex_put_conn(file.id(), EX_ELEM_BLOCK, label, nullptr, nullptr, faces.data()), "the cells of " + what);
    file.check(ex_put_entity_count_per_polyhedra(file.id(), EX_ELEM_BLOCK, label, counts.data()),
               "the face counts of " + what);
    file.check(ex_put_name(file.id(), EX_ELEM_BLOCK, label, word(label).c_str()), "the name of " + what);
  }
  std::vector<int> ids(mesh.cells.size());
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) ids[static_cast<std::size_t>(blocks.element_of_cell[c] - 1)] = static_cast<int>(c + 1);
  file.check(ex_put_id_map(file.id(), EX_ELEM_MAP, ids.data()), "the element ids");
}

void write_side_sets(ExodusFile& file, const std::vector<SideSet>& sets, const io::RegionWords& word) {
  for (std::size_t s = 0; s < sets.size(); ++s) {
    const SideSet& set = sets[s];
    const auto id = static_cast<ex_entity_id>(s + 1);
    const std::string name = word(set.from) + "_to_" + word(set.to);
    file.check(ex_put_set_param(file.id(), EX_SIDE_SET, id, static_cast<int64_t>(set.elements.size()), 0),
               "the side set " + name);
    file.check(ex_put_set(file.id(), EX_SIDE_SET, id, set.elements.data(), set.sides.data()), "the side set " + name);
    file.check(ex_put_name(file.id(), EX_SIDE_SET, id, name.c_str()), "the side set's name " + name);
    file.check(ex_put_prop(file.id(), EX_SIDE_SET, id, ExodusFile::kFromRegion, set.from), "the side set " + name);
    file.check(ex_put_prop(file.id(), EX_SIDE_SET, id, ExodusFile::kToRegion, set.to), "the side set " + name);
  }
}

void write_cell_variables(ExodusFile& file, const VoronoiMesh& mesh, const Blocks& blocks) {
  const auto& names = ExodusFile::kCellVariables;
  file.check(ex_put_variable_param(file.id(), EX_ELEM_BLOCK, static_cast<int>(names.size())), "the cell variables");
  file.check(ex_put_variable_names(file.id(), EX_ELEM_BLOCK, static_cast<int>(names.size()),
                                   const_cast<char**>(names.data())),
             "the cell variables' names");
  const double time = 0;
  file.check(ex_put_time(file.id(), 1, &time), "the time step");
  for (const auto& [label, cells] : blocks.cells) {
    std::vector<double> values(cells.size());
    for (std::size_t v = 0; v < names.size(); ++v) {
      for (std::size_t i = 0; i < cells.size(); ++i) {
        const VoronoiCell& cell = mesh.cells[cells[i]];
        values[i] = v == 0 ? static_cast<double>(cell.seed) : v < 4 ? cell.site[static_cast<int>(v - 1)] : cell.volume;
      }
      file.check(ex_put_var(file.id(), 1, EX_ELEM_BLOCK, static_cast<int>(v + 1), label,
                            static_cast<int64_t>(cells.size()), values.data()),
                 std::string("the cell variable ") + names[v]);
    }
  }
}

}  // namespace

void write_exodus(const VoronoiMesh& mesh, const std::filesystem::path& path) {
  const Blocks blocks = lay_out_blocks(mesh);
  const std::vector<SideSet> sets = side_sets(mesh, blocks);
  const io::RegionWords word(mesh);
  write_path_atomically(path, [&](const std::filesystem::path& temp) {
    ExodusFile file = ExodusFile::create(temp, path);
    ex_init_params init{};
    std::snprintf(init.title, sizeof init.title, "%s", "conforming Voronoi mesh (VoroCrust)");
    init.num_dim = 3;
    init.num_nodes = static_cast<int64_t>(mesh.points.size());
    init.num_face = static_cast<int64_t>(mesh.faces.size());
    init.num_face_blk = 1;
    init.num_elem = static_cast<int64_t>(mesh.cells.size());
    init.num_elem_blk = static_cast<int64_t>(blocks.cells.size());
    init.num_side_sets = static_cast<int64_t>(sets.size());
    file.check(ex_put_init_ext(file.id(), &init), "the header");
    write_nodes(file, mesh);
    write_face_block(file, mesh);
    write_element_blocks(file, mesh, blocks, word);
    write_side_sets(file, sets, word);
    write_cell_variables(file, mesh, blocks);
    file.close();
  });
}

}  // namespace vorocrust
