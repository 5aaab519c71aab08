// Input and output surfaces: reading, building from arrays, merging, validating, describing,
// measuring and writing them.
#include <algorithm>
#include <optional>

#include "bindings.hpp"

namespace vorocrust::python {
namespace {

Surface wrap(SurfaceMesh mesh) { return {std::make_shared<const SurfaceMesh>(std::move(mesh))}; }

// Arrays the caller gave as vertices (n x 3 numbers) and triangles (m x 3 indices) as a mesh.
Surface from_arrays(const py::object& vertices, const py::object& triangles, const std::string& name) {
  // Only safe casts for indices (int32 to int64, not 1.5 to 1): a float array of indices is a mistake.
  const auto coordinates = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(vertices);
  const auto corners = py::array_t<std::int64_t, py::array::c_style>::ensure(triangles);
  if (!coordinates) throw py::type_error(name + ": vertices must be an array of numbers (n x 3)");
  if (!corners) throw py::type_error(name + ": triangles must be an array of integer vertex indices (m x 3)");
  const auto shape = [](const py::array& a) {
    std::string text = "(";
    for (py::ssize_t d = 0; d < a.ndim(); ++d) text += (d ? ", " : "") + std::to_string(a.shape(d));
    return text + (a.ndim() == 1 ? ",)" : ")");
  };
  if (coordinates.ndim() != 2 || coordinates.shape(1) != 3) {
    throw Error(Error::Kind::Usage, "vertices must be an n x 3 array, got shape " + shape(coordinates), {.file = name});
  }
  if (corners.ndim() != 2 || corners.shape(1) != 3) {
    throw Error(Error::Kind::Usage, "triangles must be an m x 3 array, got shape " + shape(corners), {.file = name});
  }
  const std::span<const double> c(coordinates.data(), static_cast<std::size_t>(coordinates.size()));
  const std::span<const std::int64_t> t(corners.data(), static_cast<std::size_t>(corners.size()));
  py::gil_scoped_release release;
  return wrap(surface_from_arrays(c, t, name));
}

std::vector<std::filesystem::path> paths_of(const py::object& paths) {
  if (is_path(paths)) return {to_path(paths)};
  std::vector<std::filesystem::path> list;
  for (const py::handle item : paths) list.push_back(to_path(item));
  return list;
}

}  // namespace

std::vector<std::string> source_files(const SurfaceMesh& mesh) {
  std::vector<std::string> files;
  for (const FaceGroup& g : mesh.groups) {
    if (std::find(files.begin(), files.end(), g.source_file) == files.end()) files.push_back(g.source_file);
  }
  return files;
}

Surface read_surface_input(const py::object& input) {
  if (py::isinstance<Surface>(input)) return input.cast<Surface>();
  if (is_path(input) || (py::isinstance<py::sequence>(input) && !py::isinstance<py::tuple>(input))) {
    const std::vector<std::filesystem::path> files = paths_of(input);
    py::gil_scoped_release release;
    return wrap(read_meshes(files));
  }
  if (py::isinstance<py::tuple>(input) && py::len(input) == 2) {
    const py::tuple pair = input.cast<py::tuple>();
    if (is_path(pair[0]) && is_path(pair[1])) return read_surface_input(py::list(input));
    return from_arrays(pair[0], pair[1], "arrays");
  }
  throw py::type_error("a model is a file path, a list of paths, a vorocrust.Surface or a (vertices, triangles) pair");
}

void bind_surface(py::module_& m) {
  py::class_<Surface>(m, "Surface", R"doc(
A triangle surface as libvorocrust holds it: the input model or the output surface of a run.

Every face is kept as given, non-manifold edges, open boundaries and several components
included. Arrays are read-only views; a Surface never changes once made.

Surface(vertices, triangles, name="arrays") builds one from an n x 3 array of coordinates and
an m x 3 array of 0-based vertex indices, with the checks the file readers make (indices in
range, three distinct corners, finite coordinates, at least one triangle); `name` names the
surface in messages as a file name would.
)doc")
      .def(py::init([](const py::object& vertices, const py::object& triangles, const std::string& name) {
             return from_arrays(vertices, triangles, name);
           }),
           py::arg("vertices"), py::arg("triangles"), py::arg("name") = "arrays")
      .def_property_readonly(
          "vertices",
          [](py::object self) { return rows_view(self.cast<const Surface&>().mesh->vertices, self); },
          "Vertex coordinates, float64, n x 3.")
      .def_property_readonly(
          "triangles",
          [](py::object self) { return rows_view(self.cast<const Surface&>().mesh->triangles, self); },
          "Vertex indices of each triangle, uint32, m x 3; the normal follows the right-hand rule.")
      .def_property_readonly(
          "face_groups",
          [](py::object self) {
            const SurfaceMesh& s = *self.cast<const Surface&>().mesh;
            return view(s.face_group.data(), py::ssize_t(s.face_group.size()), 0, sizeof(Index), self);
          },
          "Group of each triangle (an index into `groups`), uint32, length m.")
      .def_property_readonly(
          "face_lines",
          [](py::object self) {
            const SurfaceMesh& s = *self.cast<const Surface&>().mesh;
            return view(s.face_line.data(), py::ssize_t(s.face_line.size()), 0, sizeof(std::uint32_t), self);
          },
          "1-based line of each triangle in its source file, 0 where unknown; uint32, length m.")
      .def_property_readonly(
          "groups",
          [](const Surface& s) {
            py::list names;
            for (const FaceGroup& g : s.mesh->groups) names.append(g.name);
            return names;
          },
          "Names of the face groups: OBJ groups, STL solids, input files or merged parts.")
      .def_property_readonly(
          "group_sources",
          [](const Surface& s) {
            py::list files;
            for (const FaceGroup& g : s.mesh->groups) files.append(g.source_file);
            return files;
          },
          "The file (or named source) each group was read from.")
      .def_property_readonly(
          "regions",
          [](py::object self) -> py::object {
            const SurfaceMesh& s = *self.cast<const Surface&>().mesh;
            if (!s.has_regions()) return py::none();
            static_assert(sizeof(RegionPair) == 2 * sizeof(std::int32_t));
            return view(&s.face_regions.front().back, py::ssize_t(s.face_regions.size()), 2, sizeof(RegionPair), self);
          },
          "The regions each triangle separates, int32, m x 2 (back, front; the front is the side the normal "
          "points to; -1 where unknown), as indices into `region_names`; None when the surface carries no "
          "labels. On a run's output surface they are the seeds' labels (0 outside, 1 the first material).")
      .def_property_readonly(
          "region_names", [](const Surface& s) { return s.mesh->region_names; },
          "Names of the regions an input's labels refer to.")
      .def_property_readonly("num_vertices", [](const Surface& s) { return s.mesh->num_vertices(); },
                             "Number of vertices.")
      .def_property_readonly("num_faces", [](const Surface& s) { return s.mesh->num_faces(); },
                             "Number of triangles.")
      .def(
          "describe_face", [](const Surface& s, std::size_t face) { return describe_face(*s.mesh, face); },
          py::arg("face"), "Where a face came from, as messages name it: \"face 7 (bunny.off line 12)\".")
      .def("__repr__", [](const Surface& s) {
        return "<vorocrust.Surface: " + std::to_string(s.mesh->num_vertices()) + " vertices, " +
               std::to_string(s.mesh->num_faces()) + " triangles, " + std::to_string(s.mesh->groups.size()) +
               " groups>";
      });

  m.def(
      "read_mesh",
      [](const py::object& paths) {
        const std::vector<std::filesystem::path> files = paths_of(paths);
        py::gil_scoped_release release;
        return wrap(read_meshes(files));
      },
      py::arg("paths"), R"doc(
Reads a model from OFF, OBJ, STL or PLY (format by extension, confirmed by content).

`paths` is one path or a list of them; several files merge into one model, each its own group,
sharing vertices with exactly equal coordinates so touching solids stay connected.
Raises UnreadableInputError / InvalidGeometryError naming the file and line.
)doc");

  m.def(
      "merge_surfaces",
      [](const py::object& parts) {
        std::vector<NamedSurface> named;
        for (const py::handle item : parts) {
          const py::tuple pair = py::reinterpret_borrow<py::object>(item).cast<py::tuple>();
          if (pair.size() != 2) throw py::type_error("merge_surfaces takes (name, Surface) pairs");
          named.push_back({pair[0].cast<std::string>(), *pair[1].cast<const Surface&>().mesh});
        }
        py::gil_scoped_release release;
        return wrap(merge_surfaces(named));
      },
      py::arg("parts"), R"doc(
Merges (name, Surface) pairs into one model, as reading several files does.

Each part's groups are named after the part ("name", or "name/group" when it has several), so
later stages can tell the parts (solids, materials) apart; vertices with exactly the
coordinates of a vertex of an earlier part are shared.
)doc");

  m.def(
      "validate",
      [](const Surface& surface, bool fix_orientation, bool check_self_intersections) {
        SurfaceMesh fixed = *surface.mesh;
        ValidationOptions options;
        options.fix_orientation = fix_orientation;
        options.check_self_intersections = check_self_intersections;
        ValidationReport report;
        {
          py::gil_scoped_release release;
          report = validate(fixed, options);
        }
        py::dict result;
        result["surface"] = wrap(std::move(fixed));
        result["findings"] = findings_list(report);
        result["has_errors"] = report.has_errors();
        return result;
      },
      py::arg("surface"), py::arg("fix_orientation") = true, py::arg("check_self_intersections") = true, R"doc(
Checks a surface: degenerate and duplicate faces, inconsistent orientation, inside-out shells,
self-intersections.

Returns a dict: "surface" (a new Surface with orientation problems fixed when fix_orientation
is set), "findings" (a list of dicts: severity "note"/"fixed"/"warning"/"error", code,
message naming faces and lines, count, faces, face_pairs) and "has_errors" (meshing refuses
the input).
)doc");

  m.def(
      "info",
      [](const Surface& surface, bool check_self_intersections) {
        SurfaceMesh fixed = *surface.mesh;
        std::string json;
        {
          py::gil_scoped_release release;
          const ValidationReport report = validate(fixed, {.check_self_intersections = check_self_intersections});
          json = info_json(source_files(fixed), fixed, mesh_info(fixed), report);
        }
        return parse_json(json);
      },
      py::arg("surface"), py::arg("check_self_intersections") = true, R"doc(
What `vorocrust info --json` says about a surface, as a dict: counts, components (closed,
manifold, genus, volume), groups, regions, bounding box and the validation's findings.
)doc");

  m.def(
      "measure_surface_quality",
      [](const Surface& input, const Surface& output, std::size_t samples, std::uint64_t seed) {
        QualityOptions options;
        options.random_samples = samples;
        options.seed = seed;
        std::string json;
        {
          py::gil_scoped_release release;
          json = surface_quality_json(measure_surface_quality(*input.mesh, *output.mesh, options));
        }
        return parse_json(json);
      },
      py::arg("input"), py::arg("output"), py::arg("samples") = 100000, py::arg("seed") = 0, R"doc(
Measures an output surface against its input as `vorocrust quality --json` does (paper
section 3): angles, triangle quality Q, two-sided Hausdorff distance, topology. Returns a dict
whose keys name their units.
)doc");

  m.def(
      "write_surface",
      [](const Surface& surface, const py::object& path, bool ascii) {
        const std::filesystem::path p = to_path(path);
        py::gil_scoped_release release;
        write_mesh(*surface.mesh, p, {.ascii = ascii});
      },
      py::arg("surface"), py::arg("path"), py::arg("ascii") = false, R"doc(
Writes a surface as OFF, OBJ, STL or PLY by the path's extension (STL and PLY binary unless
ascii), atomically: a failed write leaves no file. Region pairs go into PLY face properties
back_region/front_region and OBJ groups named "BACK|FRONT", as `vorocrust mesh` writes them.
)doc");
}

}  // namespace vorocrust::python
