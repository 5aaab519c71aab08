// What the parts of the `vorocrust._vorocrust` extension share: the wrappers that hand the
// library's results to Python, read-only NumPy arrays over them, and one `bind_*` per part.
//
// The library's results are immutable once made, so Python sees them through wrappers holding a
// shared_ptr: arrays of plain rows (points, triangles) are zero-copy read-only views kept alive
// by the wrapper, rows with mixed fields (seeds, Voronoi faces) are copied once into
// read-only arrays. Nothing here computes geometry: every figure comes from libvorocrust.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "vorocrust/vorocrust.hpp"

namespace vorocrust::python {

namespace py = pybind11;

// Makes an array read-only: results are shared, and writing to them would change nothing in
// the library's data but mislead.
py::array read_only(py::array a);

// An n x columns view of rows `row_bytes` apart starting at `data`, alive as long as `owner`.
template <class T>
py::array view(const T* data, py::ssize_t rows, py::ssize_t columns, py::ssize_t row_bytes, py::handle owner) {
  if (columns == 0) return read_only(py::array(py::dtype::of<T>(), {rows}, {row_bytes}, data, owner));
  return read_only(py::array(py::dtype::of<T>(), {rows, columns}, {row_bytes, py::ssize_t(sizeof(T))}, data, owner));
}

// Rows of plain numbers (Point, Triangle) as an n x columns view, alive as long as `owner`.
template <class Row>
py::array rows_view(const std::vector<Row>& rows, py::handle owner) {
  using T = std::remove_cv_t<std::remove_pointer_t<decltype(std::declval<const Row&>().data())>>;
  static_assert(sizeof(Row) % sizeof(T) == 0, "a row is a packed array of numbers");
  return view(rows.empty() ? nullptr : rows.front().data(), py::ssize_t(rows.size()),
              py::ssize_t(sizeof(Row) / sizeof(T)), sizeof(Row), owner);
}

// A read-only copy of the values `get(item)` of every item, as a 1-D array.
template <class T, class Items, class Get>
py::array column(const Items& items, Get get) {
  py::array_t<T> a(static_cast<py::ssize_t>(items.size()));
  T* out = a.mutable_data();
  for (const auto& item : items) *out++ = static_cast<T>(get(item));
  return read_only(a);
}

// A read-only n x 3 copy of `get(item)` (a Point) for every item.
template <class Items, class Get>
py::array point_rows(const Items& items, Get get) {
  py::array_t<double> a({static_cast<py::ssize_t>(items.size()), py::ssize_t(3)});
  double* out = a.mutable_data();
  for (const auto& item : items) {
    const Point& p = get(item);
    *out++ = p.x();
    *out++ = p.y();
    *out++ = p.z();
  }
  return read_only(a);
}

struct Surface {
  std::shared_ptr<const SurfaceMesh> mesh;
};

struct Seeds {
  std::shared_ptr<const std::vector<Seed>> seeds;
};

struct Balls {
  std::shared_ptr<const std::vector<Ball>> balls;
};

struct Cells {
  std::shared_ptr<const VoronoiMesh> mesh;
  // Jagged lists flattened once: face f's points are face_points[face_offsets[f]:face_offsets[f+1]].
  py::object face_points, face_offsets, cell_faces, cell_face_offsets;
};

// One job (run_job) with everything report.json says about it.
struct Run {
  Job job;
  JobResult result;
};

// The model a front end was given: a Surface, a path or a list of paths (read and merged), or a
// (vertices, triangles) pair of arrays.
Surface read_surface_input(const py::object& input);

// The files (or named sources) a mesh's groups came from, each once, in order.
std::vector<std::string> source_files(const SurfaceMesh& mesh);

Cells make_cells(std::shared_ptr<const VoronoiMesh> mesh);

// A Python object that names a file: str or os.PathLike.
bool is_path(py::handle object);
std::filesystem::path to_path(py::handle object);

// Binds `name(object, path)`: `write(wrapper, path)` run without the GIL, so other Python
// threads go on while a large file is written.
template <class Wrapper, class Write>
void def_writer(py::module_& m, const char* name, const char* object, const char* path, Write write, const char* doc) {
  m.def(
      name,
      [write](const Wrapper& wrapper, const py::object& where) {
        const std::filesystem::path p = to_path(where);
        py::gil_scoped_release release;
        write(wrapper, p);
      },
      py::arg(object), py::arg(path), doc);
}

// The findings of a validation as a list of dicts.
py::list findings_list(const ValidationReport& report);
// A JSON document of the library, as Python objects (json.loads).
py::object parse_json(const std::string& text);

// A Python value as the option's value (None: unset); Error(Usage) naming the option when it
// is of the wrong kind.
OptionValue option_value(const OptionSpec& spec, const py::handle& value);

void bind_errors(py::module_& m);
void bind_surface(py::module_& m);
void bind_seeds(py::module_& m);
void bind_cells(py::module_& m);
void bind_mesher(py::module_& m);
void bind_plane(py::module_& m);

}  // namespace vorocrust::python
