// 2D domains from Python: vorocrust.mesh2d() runs a 2D job as `vorocrust mesh2d` does and
// returns the cells as NumPy arrays.
#include "bindings.hpp"

namespace vorocrust::python {
namespace {

// Rows of (x, y) as a read-only n x 2 array.
template <class Items, class Get>
py::array xy(const Items& items, Get get) {
  py::array_t<double> a({static_cast<py::ssize_t>(items.size()), py::ssize_t{2}});
  auto w = a.mutable_unchecked<2>();
  py::ssize_t i = 0;
  for (const auto& item : items) {
    const auto p = get(item);
    w(i, 0) = p.x();
    w(i, 1) = p.y();
    ++i;
  }
  return read_only(a);
}

struct PlaneRun {
  std::shared_ptr<const PlaneJobResult> result;
  const PlaneMesh& mesh() const { return result->mesh; }
};

// A domain given as arrays: {"points": n x 2, "segments": m x 2 (indices from 0), "holes":
// k x 2, "regions": [(x, y, label), ...]}.
PlanarDomain domain_from(const py::dict& d) {
  PlanarDomain domain;
  const auto need = [&](const char* key) {
    if (!d.contains(key)) throw Error(Error::Kind::Usage, std::string("a domain needs \"") + key + "\"");
    return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(d[key]);
  };
  const auto points = need("points");
  if (!points || points.ndim() != 2 || points.shape(1) != 2) throw Error(Error::Kind::Usage, "points must be n x 2 numbers");
  for (py::ssize_t i = 0; i < points.shape(0); ++i) domain.points.emplace_back(points.at(i, 0), points.at(i, 1));
  const auto segments = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(d["segments"]);
  if (!d.contains("segments") || !segments || segments.ndim() != 2 || segments.shape(1) != 2) {
    throw Error(Error::Kind::Usage, "segments must be m x 2 point indices");
  }
  for (py::ssize_t s = 0; s < segments.shape(0); ++s) {
    std::array<Index, 2> ends{};
    for (int e = 0; e < 2; ++e) {
      const std::int64_t v = segments.at(s, e);
      if (v < 0 || v >= static_cast<std::int64_t>(domain.points.size())) {
        throw Error(Error::Kind::Usage, "segment " + std::to_string(s) + " names point " + std::to_string(v) + ", which does not exist");
      }
      ends[static_cast<std::size_t>(e)] = static_cast<Index>(v);
    }
    domain.segments.push_back(ends);
  }
  if (d.contains("holes")) {
    for (const py::handle h : d["holes"]) {
      const auto xy = h.cast<std::array<double, 2>>();
      domain.holes.emplace_back(xy[0], xy[1]);
    }
  }
  if (d.contains("regions")) {
    for (const py::handle r : d["regions"]) {
      const auto t = r.cast<py::tuple>();
      if (t.size() != 3) throw Error(Error::Kind::Usage, "a region is (x, y, label)");
      RegionPoint p;
      p.at = Point2(t[0].cast<double>(), t[1].cast<double>());
      p.label = t[2].cast<std::int32_t>();
      if (p.label < 1) throw Error(Error::Kind::Usage, "region labels start at 1");
      domain.regions.push_back(p);
    }
  }
  return domain;
}

PlaneRun run_mesh2d(const py::object& domain, const py::dict& given, const py::object& output_dir,
                    const py::object& formats, double thickness) {
  const std::vector<std::string_view> names = plane_option_names();
  MeshOptions table;
  for (const auto& [key, value] : given) {
    const std::string name = py::str(key).cast<std::string>();
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      std::string known;
      for (std::string_view n : names) known += (known.empty() ? "" : ", ") + std::string(n);
      throw Error(Error::Kind::Usage, "mesh2d() got an unknown option '" + name + "'; the options are " + known);
    }
    const OptionSpec& spec = *find_option(name);
    const OptionValue v = option_value(spec, value);
    if (v.index() != 0 || spec.default_value.index() == 0) set_option(table, spec, v);
  }
  table.check();
  PlaneJob job;
  job.options = plane_options(table);
  job.thickness = thickness;
  if (!formats.is_none()) job.formats = formats.cast<std::vector<std::string>>();
  if (!output_dir.is_none()) job.output_dir = to_path(output_dir);
  if (is_path(domain)) job.input = to_path(domain);
  else if (py::isinstance<py::dict>(domain)) job.domain = domain_from(domain.cast<py::dict>());
  else throw Error(Error::Kind::Usage, "a domain is a .poly or .obj file, or a dict of arrays (points, segments, holes, regions)");
  std::shared_ptr<PlaneJobResult> result;
  {
    py::gil_scoped_release release;
    result = std::make_shared<PlaneJobResult>(run_plane_job(job));
  }
  return PlaneRun{result};
}

}  // namespace

void bind_plane(py::module_& m) {
  py::class_<PlaneRun>(m, "PlaneMesh", "A conforming Voronoi mesh of a 2D domain (what mesh2d() returns); read-only arrays")
      .def_property_readonly("points", [](const PlaneRun& r) { return xy(r.mesh().points, [](const Point2& p) { return p; }); },
                             "n x 2 vertices")
      .def_property_readonly(
          "cells",
          [](const PlaneRun& r) {
            py::list out;
            for (const PlaneCell& c : r.mesh().cells) {
              out.append(read_only(py::array_t<Index>(static_cast<py::ssize_t>(c.points.size()), c.points.data())));
            }
            return out;
          },
          "each cell's vertices, counter-clockwise")
      .def_property_readonly("regions", [](const PlaneRun& r) { return column<std::int32_t>(r.mesh().cells, [](const PlaneCell& c) { return c.region; }); },
                             "each cell's region label")
      .def_property_readonly("areas", [](const PlaneRun& r) { return column<double>(r.mesh().cells, [](const PlaneCell& c) { return c.area; }); },
                             "each cell's area")
      .def_property_readonly("centroids", [](const PlaneRun& r) { return xy(r.mesh().cells, [](const PlaneCell& c) { return c.centroid; }); },
                             "each cell's centroid, n x 2")
      .def_property_readonly("cell_seeds", [](const PlaneRun& r) { return column<std::int64_t>(r.mesh().cells, [](const PlaneCell& c) { return c.seed; }); },
                             "each cell's seed, an index into seeds")
      .def_property_readonly(
          "seeds",
          [](const PlaneRun& r) { return xy(r.mesh().seeds, [](const Seed& s) { return s.position; }); },
          "every seed, meshed or not, n x 2")
      .def_property_readonly("seed_labels", [](const PlaneRun& r) { return column<std::int32_t>(r.mesh().seeds, [](const Seed& s) { return s.region; }); },
                             "every seed's region label (0: not meshed)")
      .def_property_readonly("region_names", [](const PlaneRun& r) { return r.mesh().region_names; }, "names by label; 0 is outside")
      .def_property_readonly("summary", [](const PlaneRun& r) { return r.result->summary; }, "the run's summary lines")
      .def_property_readonly(
          "quality",
          [](const PlaneRun& r) {
            const PlaneQuality& q = r.result->quality;
            py::dict d;
            d["cells"] = q.cells;
            d["edges"] = q.edges;
            d["boundary_edges"] = q.boundary_edges;
            d["interface_edges"] = q.interface_edges;
            d["min_angle"] = q.min_angle;
            d["max_angle"] = q.max_angle;
            d["max_aspect_ratio"] = q.max_aspect_ratio;
            d["min_shortest_edge"] = q.min_shortest_edge;
            d["max_link_angle"] = q.max_link_angle;
            d["convex"] = q.convex;
            d["area_by_region"] = q.area_by_region;
            return d;
          },
          "the figures report.json gives")
      .def("__repr__", [](const PlaneRun& r) {
        return "<vorocrust.PlaneMesh: " + std::to_string(r.mesh().cells.size()) + " cells>";
      });
  m.def("_mesh2d", &run_mesh2d, py::arg("domain"), py::arg("options"), py::arg("output_dir"), py::arg("formats"),
        py::arg("thickness"));
  m.attr("PLANE_OPTIONS") = [] {
    py::list names;
    for (std::string_view n : plane_option_names()) names.append(std::string(n));
    return names;
  }();
  m.attr("PLANE_FORMATS") = plane_format_names();
}

}  // namespace vorocrust::python
