// vorocrust._vorocrust: the library's public API for Python. The package `vorocrust` re-exports
// it; see python/README.md for the whole interface.
#include "bindings.hpp"

namespace vorocrust::python {

py::array read_only(py::array a) {
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

bool is_path(py::handle object) {
  return py::isinstance<py::str>(object) || py::hasattr(object, "__fspath__");
}

std::filesystem::path to_path(py::handle object) { return object.cast<std::filesystem::path>(); }

py::list findings_list(const ValidationReport& report) {
  py::list list;
  for (const Finding& f : report.findings) {
    py::dict d;
    d["severity"] = to_string(f.severity);
    d["code"] = f.code;
    d["message"] = f.message;
    d["count"] = f.count;
    d["faces"] = f.faces;
    py::list pairs;
    for (const auto& [a, b] : f.face_pairs) pairs.append(py::make_tuple(a, b));
    d["face_pairs"] = pairs;
    list.append(d);
  }
  return list;
}

py::object parse_json(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

PYBIND11_MODULE(_vorocrust, m) {
  m.doc() = "libvorocrust for Python: conforming Voronoi meshing without clipping (the package `vorocrust` "
            "re-exports everything here).";
  m.attr("__version__") = VOROCRUST_VERSION;
  bind_errors(m);
  bind_surface(m);
  bind_seeds(m);
  bind_cells(m);
  bind_mesher(m);
  bind_plane(m);
}

}  // namespace vorocrust::python
