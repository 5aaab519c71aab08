// The conforming Voronoi mesh: computing it from seeds, its arrays, and its exports.
#include <optional>
#include <tuple>

#include "bindings.hpp"

namespace vorocrust::python {
namespace {

// Flattens lists (each face's points, each cell's faces) into one index array and offsets.
template <class Items, class Get>
std::pair<py::array, py::array> flatten(const Items& items, Get get) {
  std::size_t total = 0;
  for (const auto& item : items) total += get(item).size();
  py::array_t<std::uint32_t> values(static_cast<py::ssize_t>(total));
  py::array_t<std::int64_t> offsets(static_cast<py::ssize_t>(items.size() + 1));
  std::uint32_t* v = values.mutable_data();
  std::int64_t* o = offsets.mutable_data();
  std::int64_t at = 0;
  *o++ = 0;
  for (const auto& item : items) {
    for (const Index i : get(item)) *v++ = i;
    at += static_cast<std::int64_t>(get(item).size());
    *o++ = at;
  }
  return {read_only(values), read_only(offsets)};
}

// The entries offsets[i]:offsets[i+1] of values, checked.
py::array slice(const py::object& values, const py::object& offsets, py::ssize_t i, const char* what) {
  const auto o = offsets.cast<py::array_t<std::int64_t>>();
  if (i < 0) i += o.shape(0) - 1;
  if (i < 0 || i + 1 >= o.shape(0)) throw py::index_error(std::string(what) + " index out of range");
  return values[py::slice(o.at(i), o.at(i + 1), 1)];
}

}  // namespace

Cells make_cells(std::shared_ptr<const VoronoiMesh> mesh) {
  Cells c{std::move(mesh), {}, {}, {}, {}};
  std::tie(c.face_points, c.face_offsets) = flatten(c.mesh->faces, [](const VoronoiFace& f) -> const auto& { return f.points; });
  std::tie(c.cell_faces, c.cell_face_offsets) = flatten(c.mesh->cells, [](const VoronoiCell& x) -> const auto& { return x.faces; });
  return c;
}

void bind_cells(py::module_& m) {
  py::class_<Cells>(m, "Cells", R"doc(
The conforming Voronoi mesh of a seed set: one convex, closed polyhedral cell per material seed.

A point shared by several cells is one point; a face between two cells is listed once, its
polygon's normal (right-hand rule) pointing from its owner cell to the other side. Cells are
numbered in seed order. Jagged lists are flattened: face f's points are
face_points[face_offsets[f]:face_offsets[f + 1]] (or face(f)), cell c's faces
cell_faces[cell_face_offsets[c]:cell_face_offsets[c + 1]] (or cell(c)). Arrays are read-only.
Made by compute_cells() or a mesh() run.
)doc")
      .def_property_readonly(
          "points",
          [](py::object self) { return rows_view(self.cast<const Cells&>().mesh->points, self); },
          "The Voronoi vertices, float64, p x 3.")
      .def_readonly("face_points", &Cells::face_points, "Point indices of all faces' polygons, uint32, flattened.")
      .def_readonly("face_offsets", &Cells::face_offsets, "Where each face's polygon starts in face_points, int64, f + 1.")
      .def_property_readonly(
          "owner", [](const Cells& c) { return column<std::int32_t>(c.mesh->faces, [](const VoronoiFace& f) { return f.owner; }); },
          "The cell each face's normal points away from, int32.")
      .def_property_readonly(
          "neighbour",
          [](const Cells& c) { return column<std::int32_t>(c.mesh->faces, [](const VoronoiFace& f) { return f.neighbour; }); },
          "The cell across each face, int32; -1 where the other side is no material cell (a boundary face).")
      .def_property_readonly(
          "owner_seed",
          [](const Cells& c) { return column<std::uint32_t>(c.mesh->faces, [](const VoronoiFace& f) { return f.owner_seed; }); },
          "The seed of each face's owner cell, uint32.")
      .def_property_readonly(
          "neighbour_seed",
          [](const Cells& c) {
            return column<std::uint32_t>(c.mesh->faces, [](const VoronoiFace& f) { return f.neighbour_seed; });
          },
          "The seed across each face, a cell's or not, uint32.")
      .def_property_readonly(
          "face_regions",
          [](const Cells& c) {
            py::array_t<std::int32_t> a({static_cast<py::ssize_t>(c.mesh->faces.size()), py::ssize_t(2)});
            std::int32_t* out = a.mutable_data();
            for (const VoronoiFace& f : c.mesh->faces) {
              *out++ = f.regions.back;
              *out++ = f.regions.front;
            }
            return read_only(a);
          },
          "The regions each face separates, int32, f x 2: the owner's region, then the region across.")
      .def_readonly("cell_faces", &Cells::cell_faces, "Face indices of all cells, uint32, flattened.")
      .def_readonly("cell_face_offsets", &Cells::cell_face_offsets,
                    "Where each cell's faces start in cell_faces, int64, c + 1.")
      .def_property_readonly(
          "cell_seeds",
          [](const Cells& c) { return column<std::uint32_t>(c.mesh->cells, [](const VoronoiCell& x) { return x.seed; }); },
          "The seed of each cell, uint32.")
      .def_property_readonly(
          "materials",
          [](const Cells& c) { return column<std::int32_t>(c.mesh->cells, [](const VoronoiCell& x) { return x.region; }); },
          "The material (region) of each cell, int32.")
      .def_property_readonly(
          "volumes",
          [](const Cells& c) { return column<double>(c.mesh->cells, [](const VoronoiCell& x) { return x.volume; }); },
          "The volume of each cell, float64.")
      .def_property_readonly(
          "centroids", [](const Cells& c) { return point_rows(c.mesh->cells, [](const VoronoiCell& x) { return x.centroid; }); },
          "The centroid of each cell, float64, c x 3.")
      .def_property_readonly(
          "sites", [](const Cells& c) { return point_rows(c.mesh->cells, [](const VoronoiCell& x) { return x.site; }); },
          "The seed of each cell, float64, c x 3: the node the links between neighbouring cells cross their faces "
          "at right angles from.")
      .def_property(
          "region_names", [](const Cells& c) { return c.mesh->region_names; },
          [](Cells& c, const std::vector<std::string>& names) {
            auto named = std::make_shared<VoronoiMesh>(*c.mesh);
            named->region_names = names;
            c.mesh = std::move(named);
          },
          "The regions' names by label, as the writers use them (empty: outside and material<N>); settable, for "
          "cells built from seeds alone.")
      .def_property_readonly("num_points", [](const Cells& c) { return c.mesh->points.size(); }, "Number of points.")
      .def_property_readonly("num_faces", [](const Cells& c) { return c.mesh->faces.size(); }, "Number of faces.")
      .def_property_readonly("num_cells", [](const Cells& c) { return c.mesh->cells.size(); }, "Number of cells.")
      .def(
          "face", [](const Cells& c, py::ssize_t f) { return slice(c.face_points, c.face_offsets, f, "face"); },
          py::arg("f"), "The point indices of face f's polygon, in order.")
      .def(
          "cell", [](const Cells& c, py::ssize_t i) { return slice(c.cell_faces, c.cell_face_offsets, i, "cell"); },
          py::arg("c"), "The face indices of cell c.")
      .def("__len__", [](const Cells& c) { return c.mesh->cells.size(); })
      .def("__repr__", [](const Cells& c) {
        return "<vorocrust.Cells: " + std::to_string(c.mesh->cells.size()) + " cells, " +
               std::to_string(c.mesh->faces.size()) + " faces, " + std::to_string(c.mesh->points.size()) + " points>";
      });

  m.def(
      "compute_cells",
      [](const py::object& seeds, const std::optional<std::vector<std::int32_t>>& materials, int threads,
         const std::optional<std::vector<std::string>>& region_names) {
        std::shared_ptr<const std::vector<Seed>> input;
        std::vector<std::string> names;
        if (is_path(seeds)) {
          const std::filesystem::path p = to_path(seeds);
          py::gil_scoped_release release;
          input = std::make_shared<const std::vector<Seed>>(read_seeds_csv(p));
          names = run_report_regions(p.parent_path() / "report.json");
        } else {
          input = seeds.cast<const Seeds&>().seeds;
        }
        CellsOptions options;
        if (materials) options.materials = *materials;
        options.threads = threads;
        if (threads < 0) throw Error(Error::Kind::Usage, "threads must be 0 (all) or positive");
        std::shared_ptr<const VoronoiMesh> mesh;
        {
          py::gil_scoped_release release;
          VoronoiMesh cells = compute_cells(*input, options);
          cells.region_names = region_names ? *region_names : std::move(names);
          mesh = std::make_shared<const VoronoiMesh>(std::move(cells));
        }
        return make_cells(std::move(mesh));
      },
      py::arg("seeds"), py::arg("materials") = py::none(), py::arg("threads") = 0,
      py::arg("region_names") = py::none(), R"doc(
The conforming Voronoi mesh of a seed set, as `vorocrust cells SEEDS` builds it.

`seeds` is a Seeds or the path of a seeds.csv; `materials` the labels that get cells (default:
every label > 0); `threads` 0 for all cores (the result does not depend on it); `region_names`
the regions' names by label for the writers (default: those of the report.json beside a
seeds.csv, as `vorocrust cells` reads them, else "outside" and "material<N>"). Raises
InvalidGeometryError when no seed is a material or a material cell is not bounded by other
seeds (outside seeds must surround the materials).
)doc");

  def_writer<Cells>(
      m, "write_vtu", "cells", "path", [](const Cells& c, const auto& p) { write_vtu(*c.mesh, p); }, R"doc(
Writes the cells as a VTK XML unstructured grid (mesh.vtu: polyhedron cells, cell data
material, seed, volume, aspect_ratio) that VTK 9.1 and ParaView read; atomically.
)doc");
  def_writer<Cells>(
      m, "write_tets", "cells", "path", [](const Cells& c, const auto& p) { write_tets_vtu(*c.mesh, p); }, R"doc(
Writes the tetrahedra dual to clipped cells (Yan et al. 2011, 5.2: the Delaunay tetrahedra of the
seeds whose circumcentre lies inside their material) as tets.vtu: a point per cell at its seed
(point data seed), a tetrahedron per Voronoi vertex inside a material with cell data material,
min_dihedral, max_dihedral (degrees), radius_ratio and q4. Atomically.
)doc");
  def_writer<Cells>(
      m, "write_tough", "cells", "path", [](const Cells& c, const auto& p) { write_tough_mesh(*c.mesh, p); }, R"doc(
Writes the cells as a TOUGH MESH file (ELEME: name, material, volume, the seed as node; CONNE:
the two cells, half the seed link on each side, face area, gravity cosine), atomically.
)doc");
  def_writer<Cells>(
      m, "write_pflotran", "cells", "folder", [](const Cells& c, const auto& p) { write_pflotran(*c.mesh, p); },
      R"doc(
Writes the cells as PFLOTRAN's explicit unstructured grid into a folder: mesh.uge (CELLS and
CONNECTIONS), a cell-id list <material>.txt per material and boundary connections <patch>.ex per
boundary patch. Each file is written atomically.
)doc");
  def_writer<Cells>(
      m, "write_exodus", "cells", "path", [](const Cells& c, const auto& p) { write_exodus(*c.mesh, p); }, R"doc(
Writes the cells as an Exodus II file (mesh.exo): one NFACED block per material named after it,
its faces in one NSIDED block, side sets per boundary patch and interface, and the cell variables
seed, sitex/y/z and volume. ParaView opens it with its Exodus II reader. Atomically.
)doc");
  m.def(
      "read_exodus",
      [](const py::object& where) {
        const std::filesystem::path p = to_path(where);
        std::shared_ptr<const VoronoiMesh> mesh;
        {
          py::gil_scoped_release release;
          mesh = std::make_shared<const VoronoiMesh>(read_exodus(p));
        }
        return make_cells(std::move(mesh));
      },
      py::arg("path"), R"doc(
Reads an Exodus II file as write_exodus writes it back into Cells: the materials from the block
ids, region_names from the block and side set names, volumes and centroids measured from the
faces. Raises UnreadableInputError, naming the file, for anything else.
)doc");
  def_writer<Cells>(
      m, "write_openfoam", "cells", "case_dir", [](const Cells& c, const auto& p) { write_openfoam_case(*c.mesh, p); },
      R"doc(
Writes the cells as an OpenFOAM case folder (constant/polyMesh and system/) on which
`checkMesh -case CASE_DIR` runs as it is: boundary patches by region pair, one cell zone per
material. Each file is written atomically.
)doc");
}

}  // namespace vorocrust::python
