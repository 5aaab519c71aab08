#include <exodusII.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#include "geometry/measure_cells.hpp"
#include "io/exodus_file.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/exodus.hpp"

namespace vorocrust {

namespace {

using io::ExodusFile;

// A block's parameters, its list of entries (nodes of faces, or faces of elements) and the size
// of each entry, checked to agree.
struct PolyBlock {
  ex_block param{};
  std::vector<int> list, counts;
  std::string name;
};

PolyBlock read_poly_block(const ExodusFile& file, ex_entity_type type, ex_entity_id id, const char* topology,
                          const std::string& what) {
  PolyBlock b;
  b.param.id = id;
  b.param.type = type;
  file.check(ex_get_block_param(file.id(), &b.param), what);
  if (strncasecmp(b.param.topology, topology, std::strlen(topology) + 1) != 0) {
    throw Error(Error::Kind::UnreadableInput,
                what + " is of " + b.param.topology + " entries, where " + topology + " ones are expected");
  }
  const int64_t total = type == EX_FACE_BLOCK ? b.param.num_nodes_per_entry : b.param.num_faces_per_entry;
  b.list.resize(static_cast<std::size_t>(std::max<int64_t>(total, 0)));
  b.counts.resize(static_cast<std::size_t>(std::max<int64_t>(b.param.num_entry, 0)));
  file.check(ex_get_conn(file.id(), type, id, type == EX_FACE_BLOCK ? b.list.data() : nullptr, nullptr,
                         type == EX_ELEM_BLOCK ? b.list.data() : nullptr),
             what);
  file.check(ex_get_entity_count_per_polyhedra(file.id(), type, id, b.counts.data()), what);
  if (std::any_of(b.counts.begin(), b.counts.end(), [](int n) { return n < 1; }) ||
      std::accumulate(b.counts.begin(), b.counts.end(), int64_t{0}) != total) {
    throw Error(Error::Kind::UnreadableInput, what + ": its entries' sizes do not add up to its list");
  }
  std::vector<char> name(static_cast<std::size_t>(ex_inquire_int(file.id(), EX_INQ_DB_MAX_USED_NAME_LENGTH)) + 82, '\0');
  file.check(ex_get_name(file.id(), type, id, name.data()), what);
  b.name = name.data();
  return b;
}

std::vector<ex_entity_id> ids_of(const ExodusFile& file, ex_entity_type type, ex_inquiry count, const char* what) {
  std::vector<int> ids(static_cast<std::size_t>(std::max<int64_t>(ex_inquire_int(file.id(), count), 0)));
  if (!ids.empty()) file.check(ex_get_ids(file.id(), type, ids.data()), what);
  return {ids.begin(), ids.end()};
}

// Each cell's variable values, by the writer's names; cells absent keep NaN.
std::map<std::string, std::vector<double>> cell_variables(const ExodusFile& file, const std::vector<PolyBlock>& blocks,
                                                          const std::vector<std::size_t>& first_cell,
                                                          const std::vector<std::size_t>& cell_of_element) {
  std::map<std::string, std::vector<double>> out;
  int count = 0;
  if (ex_get_variable_param(file.id(), EX_ELEM_BLOCK, &count) < 0 || count <= 0 || ex_inquire_int(file.id(), EX_INQ_TIME) < 1) {
    return out;
  }
  std::vector<std::vector<char>> buffers(static_cast<std::size_t>(count), std::vector<char>(128, '\0'));
  std::vector<char*> names;
  for (auto& b : buffers) names.push_back(b.data());
  file.check(ex_get_variable_names(file.id(), EX_ELEM_BLOCK, count, names.data()), "the cell variables' names");
  for (int v = 0; v < count; ++v) {
    const std::string name = names[static_cast<std::size_t>(v)];
    if (std::find_if(ExodusFile::kCellVariables.begin(), ExodusFile::kCellVariables.end(),
                     [&](const char* n) { return name == n; }) == ExodusFile::kCellVariables.end()) {
      continue;
    }
    std::vector<double>& values = out[name];
    values.assign(cell_of_element.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t b = 0; b < blocks.size(); ++b) {
      std::vector<double> block(blocks[b].counts.size());
      if (block.empty()) continue;
      file.check(ex_get_var(file.id(), 1, EX_ELEM_BLOCK, v + 1, blocks[b].param.id,
                            static_cast<int64_t>(block.size()), block.data()),
                 "the cell variable " + name);
      for (std::size_t e = 0; e < block.size(); ++e) values[cell_of_element[first_cell[b] + e]] = block[e];
    }
  }
  return out;
}

}  // namespace

VoronoiMesh read_exodus(const std::filesystem::path& path) {
  const ExodusFile file = ExodusFile::open(path);
  const auto fail = [&](const std::string& why) {
    throw Error(Error::Kind::UnreadableInput, why, {.file = path.string()});
  };
  try {
    ex_init_params init{};
    file.check(ex_get_init_ext(file.id(), &init), "the header");
    if (init.num_dim != 3) fail("the mesh is not three-dimensional");
    if (init.num_face_blk != 1) fail("a Voronoi mesh's file has one face block, this one " + std::to_string(init.num_face_blk));
    VoronoiMesh mesh;

    std::vector<double> xyz[3];
    for (auto& v : xyz) v.resize(static_cast<std::size_t>(std::max<int64_t>(init.num_nodes, 0)));
    if (init.num_nodes > 0) file.check(ex_get_coord(file.id(), xyz[0].data(), xyz[1].data(), xyz[2].data()), "the nodes");
    for (std::size_t p = 0; p < xyz[0].size(); ++p) mesh.points.emplace_back(xyz[0][p], xyz[1][p], xyz[2][p]);

    const std::vector<ex_entity_id> face_blocks = ids_of(file, EX_FACE_BLOCK, EX_INQ_FACE_BLK, "the face block");
    const PolyBlock faces = read_poly_block(file, EX_FACE_BLOCK, face_blocks.at(0), "NSIDED", "the face block");
    mesh.faces.resize(faces.counts.size());
    for (std::size_t f = 0, k = 0; f < faces.counts.size(); ++f) {
      for (int i = 0; i < faces.counts[f]; ++i, ++k) {
        const int node = faces.list[k];
        if (node < 1 || static_cast<std::size_t>(node) > mesh.points.size()) {
          fail("face " + std::to_string(f + 1) + " has node " + std::to_string(node) + ", beyond the " +
               std::to_string(mesh.points.size()) + " nodes");
        }
        mesh.faces[f].points.push_back(static_cast<Index>(node - 1));
      }
    }

    // Element blocks in file order; cells in the order of the element id map, when it is one.
    std::vector<PolyBlock> blocks;
    std::vector<std::size_t> first_element;
    std::size_t elements = 0;
    for (ex_entity_id id : ids_of(file, EX_ELEM_BLOCK, EX_INQ_ELEM_BLK, "the element blocks")) {
      blocks.push_back(read_poly_block(file, EX_ELEM_BLOCK, id, "NFACED", "element block " + std::to_string(id)));
      first_element.push_back(elements);
      elements += blocks.back().counts.size();
    }
    std::vector<int> ids(elements);
    if (elements > 0) file.check(ex_get_id_map(file.id(), EX_ELEM_MAP, ids.data()), "the element ids");
    std::vector<std::size_t> cell_of_element(elements);
    std::vector<char> taken(elements, 0);
    bool permutation = true;
    for (std::size_t e = 0; e < elements && permutation; ++e) {
      const auto c = static_cast<std::size_t>(ids[e] - 1);
      permutation = ids[e] >= 1 && c < elements && !taken[c];
      if (permutation) taken[c] = 1, cell_of_element[e] = c;
    }
    if (!permutation) std::iota(cell_of_element.begin(), cell_of_element.end(), std::size_t{0});

    mesh.cells.resize(elements);
    std::map<std::int32_t, std::string> names;
    for (std::size_t b = 0; b < blocks.size(); ++b) {
      const auto label = static_cast<std::int32_t>(blocks[b].param.id);
      if (!blocks[b].name.empty()) names[label] = blocks[b].name;
      for (std::size_t e = 0, k = 0; e < blocks[b].counts.size(); ++e) {
        VoronoiCell& cell = mesh.cells[cell_of_element[first_element[b] + e]];
        cell.region = label;
        for (int i = 0; i < blocks[b].counts[e]; ++i, ++k) {
          const int face = blocks[b].list[k];
          if (face < 1 || static_cast<std::size_t>(face) > mesh.faces.size()) {
            fail("element block " + std::to_string(label) + " lists face " + std::to_string(face) + ", beyond the " +
                 std::to_string(mesh.faces.size()) + " faces");
          }
          cell.faces.push_back(static_cast<Index>(face - 1));
        }
      }
    }
    // Owner and neighbour: the first and second cell listing a face, in cell order.
    for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
      for (Index f : mesh.cells[c].faces) {
        VoronoiFace& face = mesh.faces[f];
        if (face.owner == kNoCell) face.owner = static_cast<std::int32_t>(c);
        else if (face.neighbour == kNoCell) face.neighbour = static_cast<std::int32_t>(c);
        else fail("face " + std::to_string(f + 1) + " belongs to more than two cells");
      }
    }
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
      if (mesh.faces[f].owner == kNoCell) fail("face " + std::to_string(f + 1) + " belongs to no cell");
    }

    const auto variables = cell_variables(file, blocks, first_element, cell_of_element);
    const auto variable = [&](const char* name, std::size_t c) {
      const auto it = variables.find(name);
      return it == variables.end() ? std::numeric_limits<double>::quiet_NaN() : it->second[c];
    };
    for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
      VoronoiCell& cell = mesh.cells[c];
      const double seed = variable("seed", c);
      cell.seed = seed >= 0 && seed < 4294967296.0 ? static_cast<Index>(seed) : static_cast<Index>(c);
      cell.site = Point(variable("sitex", c), variable("sitey", c), variable("sitez", c));
    }
    for (VoronoiFace& face : mesh.faces) {
      const VoronoiCell& owner = mesh.cells[static_cast<std::size_t>(face.owner)];
      face.owner_seed = owner.seed;
      face.regions.back = owner.region;
      if (face.neighbour != kNoCell) {
        const VoronoiCell& neighbour = mesh.cells[static_cast<std::size_t>(face.neighbour)];
        face.neighbour_seed = neighbour.seed;
        face.regions.front = neighbour.region;
      } else {
        face.neighbour_seed = owner.seed;
        face.regions.front = kOutsideRegion;
      }
    }

    // The regions across boundary faces, from the side sets' TO_REGION, and their names.
    for (ex_entity_id id : ids_of(file, EX_SIDE_SET, EX_INQ_SIDE_SETS, "the side sets")) {
      const std::string what = "side set " + std::to_string(id);
      int64_t count = 0, factors = 0;
      file.check(ex_get_set_param(file.id(), EX_SIDE_SET, id, &count, &factors), what);
      std::vector<int> element(static_cast<std::size_t>(std::max<int64_t>(count, 0))), side(element.size());
      if (!element.empty()) file.check(ex_get_set(file.id(), EX_SIDE_SET, id, element.data(), side.data()), what);
      int to = kOutsideRegion;
      if (ex_get_prop(file.id(), EX_SIDE_SET, id, ExodusFile::kToRegion, &to) < 0) continue;
      for (std::size_t s = 0; s < element.size(); ++s) {
        if (element[s] < 1 || static_cast<std::size_t>(element[s]) > elements) fail(what + " names element " + std::to_string(element[s]));
        const VoronoiCell& cell = mesh.cells[cell_of_element[static_cast<std::size_t>(element[s] - 1)]];
        if (side[s] < 1 || static_cast<std::size_t>(side[s]) > cell.faces.size()) fail(what + " names side " + std::to_string(side[s]));
        VoronoiFace& face = mesh.faces[cell.faces[static_cast<std::size_t>(side[s] - 1)]];
        if (face.neighbour == kNoCell) face.regions.front = to;
      }
      int from = kOutsideRegion;
      std::vector<char> name(128, '\0');
      if (ex_get_prop(file.id(), EX_SIDE_SET, id, ExodusFile::kFromRegion, &from) >= 0 && names.count(from) &&
          !names.count(to) && ex_get_name(file.id(), EX_SIDE_SET, id, name.data()) >= 0) {
        // "<from's name>_to_<to's name>", as the writer names it.
        const std::string set_name = name.data(), prefix = names[from] + "_to_";
        if (set_name.starts_with(prefix) && set_name.size() > prefix.size()) names[to] = set_name.substr(prefix.size());
      }
    }
    if (!names.empty()) {
      mesh.region_names.resize(static_cast<std::size_t>(std::max(names.rbegin()->first, 0) + 1));
      for (std::size_t label = 0; label < mesh.region_names.size(); ++label) {
        const auto it = names.find(static_cast<std::int32_t>(label));
        mesh.region_names[label] = it != names.end() ? it->second
                                   : label == 0       ? std::string("outside")
                                                      : "material" + std::to_string(label);
      }
    }
    for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
      if (mesh.cells[c].faces.empty()) fail("element " + std::to_string(c + 1) + " has no face");
    }
    geometry::measure_cells(mesh);
    return mesh;
  } catch (const std::out_of_range&) {
    fail("the file has no face block");
  }
  return {};
}

}  // namespace vorocrust
