// The whole pipeline from Python: vorocrust.mesh() (a job, as `vorocrust mesh` runs it), the
// option table it is made from, and the MeshResult it returns.
#include <cmath>
#include <limits>

#include "bindings.hpp"
#include "progress_bridge.hpp"

namespace vorocrust::python {
namespace {

// A result's part as a Python object sharing the run's lifetime.
template <class Part>
std::shared_ptr<const Part> part_of(const std::shared_ptr<const Run>& run, const Part& part) {
  return std::shared_ptr<const Part>(run, &part);
}

// The MeshResult Python sees; parts are wrapped once and handed out again on each access.
struct MeshRun {
  std::shared_ptr<const Run> run;
  py::object seeds, surface, cells, balls, input, smoothed_input;

  template <class Make>
  py::object cached(py::object& slot, Make make) {
    if (!slot) slot = make();
    return slot;
  }
  const MeshResult& mesh() const { return run->result.mesh; }
  bool reached(Stage stage) const { return run->job.options.stop_after >= stage; }
};

[[noreturn]] void wrong_type(const OptionSpec& spec, const char* what, const py::handle& value) {
  throw Error(Error::Kind::Usage,
              std::string(spec.name) + " takes " + what + ", got " + py::repr(value).cast<std::string>(),
              {.option = std::string(spec.name)});
}

}  // namespace

OptionValue option_value(const OptionSpec& spec, const py::handle& value) {
  if (value.is_none()) return std::monostate{};
  const bool is_bool = py::isinstance<py::bool_>(value);
  const bool is_int = py::isinstance<py::int_>(value) && !is_bool;
  switch (spec.kind) {
    case OptionKind::Flag:
      if (!is_bool) wrong_type(spec, "True or False", value);
      return value.cast<bool>();
    case OptionKind::Integer:
      if (!is_int) wrong_type(spec, "a whole number", value);
      try {
        return value.cast<std::int64_t>();
      } catch (const py::cast_error&) {
        throw Error(Error::Kind::Usage, std::string(spec.name) + " is out of its range (" + range_text(spec) + "), got " +
                                            py::str(value).cast<std::string>(),
                    {.option = std::string(spec.name)});
      }
    case OptionKind::Real:
      if (!is_int && !py::isinstance<py::float_>(value)) wrong_type(spec, "a number", value);
      return value.cast<double>();
    case OptionKind::Choice:
      if (!py::isinstance<py::str>(value)) wrong_type(spec, "a name", value);
      return value.cast<std::string>();
    case OptionKind::Choices: {
      if (py::isinstance<py::str>(value) || !py::isinstance<py::sequence>(value)) wrong_type(spec, "a list of names", value);
      std::vector<std::string> names;
      for (const py::handle item : value) {
        if (!py::isinstance<py::str>(item)) wrong_type(spec, "a list of names", value);
        names.push_back(item.cast<std::string>());
      }
      return names;
    }
    case OptionKind::File:
      if (!is_path(value)) wrong_type(spec, "a file path", value);
      return to_path(value).string();
    case OptionKind::Box: {
      if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value) || py::len(value) != 6) {
        wrong_type(spec, "six numbers (xmin, ymin, zmin, xmax, ymax, zmax)", value);
      }
      std::array<double, 6> box{};
      for (std::size_t k = 0; k < 6; ++k) box[k] = py::float_(value[py::int_(k)]).cast<double>();
      return box;
    }
  }
  wrong_type(spec, "a value", value);
}

namespace {

py::object python_value(const OptionValue& value) {
  return std::visit(
      [](const auto& v) -> py::object {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::monostate>) {
          return py::none();
        } else if constexpr (std::is_same_v<T, std::array<double, 6>>) {
          return py::make_tuple(v[0], v[1], v[2], v[3], v[4], v[5]);
        } else {
          return py::cast(v);
        }
      },
      value);
}

MeshRun run_mesh(const py::object& model, const py::dict& given, const py::object& output_dir, const py::object& progress) {
  auto run = std::make_shared<Run>();
  Job& job = run->job;
  for (const auto& [key, value] : given) {
    const std::string name = py::str(key).cast<std::string>();
    const OptionSpec* spec = find_option(name);
    if (spec == nullptr || !(spec->front_ends & kPython)) {
      std::string known;
      for (const OptionSpec& s : mesh_option_specs()) known += (known.empty() ? "" : ", ") + std::string(s.name);
      throw Error(Error::Kind::Usage, "mesh() got an unknown option '" + name + "'; the options are " + known);
    }
    const OptionValue v = option_value(*spec, value);
    if (v.index() != 0 || spec->default_value.index() == 0) set_option(job.options, *spec, v);
  }
  job.options.check();
  if (!output_dir.is_none()) job.output_dir = to_path(output_dir);
  // Files are read by the job (their reading is timed and reported); a model in memory is taken.
  const bool paths = is_path(model) || (py::isinstance<py::list>(model) && py::len(model) > 0 &&
                                         std::all_of(model.begin(), model.end(), [](py::handle h) { return is_path(h); }));
  if (paths) {
    if (is_path(model)) job.inputs.push_back(to_path(model));
    else for (const py::handle item : model) job.inputs.push_back(to_path(item));
  } else {
    const Surface surface = read_surface_input(model);
    job.model = *surface.mesh;
    for (const std::string& file : source_files(*surface.mesh)) job.inputs.emplace_back(file);
  }
  ProgressBridge bridge(progress);
  try {
    py::gil_scoped_release release;
    run->result = run_job(job, bridge.callback());
  } catch (const Error& e) {
    if (e.kind() == Error::Kind::Cancelled) bridge.rethrow();
    throw;
  }
  return MeshRun{std::move(run), {}, {}, {}, {}, {}, {}};
}

py::list lines(const std::vector<std::string>& text) {
  py::list out;
  for (const std::string& line : text) out.append(spell_options(line, Spelling::Python));
  return out;
}

}  // namespace

void bind_mesher(py::module_& m) {
  py::class_<MeshRun>(m, "MeshResult", R"doc(
What one mesh() run made, with everything `vorocrust mesh` writes about it.

Parts the run did not reach are None: `surface` before stop_after="surface", `cells` before
stop_after="cells". Figures (features, refinement, slivers, surface quality) are in report(),
the same document as the CLI's OUTDIR/report.json; `summary` holds the lines the CLI prints.
)doc")
      .def_property_readonly(
          "balls",
          [](MeshRun& r) { return r.cached(r.balls, [&] { return py::cast(Balls{part_of(r.run, r.mesh().balls)}); }); },
          "The protecting balls (Balls).")
      .def_property_readonly(
          "seeds",
          [](MeshRun& r) {
            return r.cached(r.seeds, [&]() -> py::object {
              if (!r.reached(Stage::Surface)) return py::none();
              return py::cast(Seeds{part_of(r.run, r.mesh().seeds)});
            });
          },
          "The seeds (Seeds): surface seeds first, two per seed pair, then interior and outside seeds "
          "once the run reaches the cells; None before stop_after=\"surface\".")
      .def_property_readonly(
          "surface",
          [](MeshRun& r) {
            return r.cached(r.surface, [&]() -> py::object {
              if (!r.reached(Stage::Surface)) return py::none();
              return py::cast(Surface{part_of(r.run, r.mesh().surface)});
            });
          },
          "The output surface (Surface): triangles of ball centres between seeds of different regions, "
          "`regions` holding the region pair of each face (normals point to the lower region number); None "
          "before stop_after=\"surface\".")
      .def_property_readonly(
          "cells",
          [](MeshRun& r) {
            return r.cached(r.cells, [&]() -> py::object {
              if (!r.reached(Stage::Cells)) return py::none();
              return py::cast(make_cells(part_of(r.run, r.mesh().cells)));
            });
          },
          "The conforming Voronoi mesh (Cells) of the material seeds; None before stop_after=\"cells\".")
      .def_property_readonly(
          "input",
          [](MeshRun& r) { return r.cached(r.input, [&] { return py::cast(Surface{part_of(r.run, r.run->result.input)}); }); },
          "The input surface as meshed: validated, its orientation fixed.")
      .def_property_readonly(
          "smoothed_input",
          [](MeshRun& r) {
            return r.cached(r.smoothed_input, [&] { return py::cast(Surface{part_of(r.run, r.mesh().smoothed_input)}); });
          },
          "The surface the balls cover: the input after patch smoothing (the input itself without it).")
      .def_property_readonly(
          "validation", [](const MeshRun& r) { return findings_list(r.run->result.validation); },
          "The input validation's findings, as validate() gives them.")
      .def_property_readonly(
          "surface_quality",
          [](const MeshRun& r) -> py::object {
            if (!r.mesh().surface_quality) return py::none();
            return parse_json(surface_quality_json(*r.mesh().surface_quality));
          },
          "The output surface measured against the input (dict, as measure_surface_quality()), or None.")
      .def_property_readonly(
          "timings",
          [](const MeshRun& r) {
            py::list list;
            for (const PhaseTiming& t : r.run->result.timings) list.append(py::make_tuple(t.name, t.seconds));
            return list;
          },
          "(phase, seconds) for every phase of the run, reading and writing included, as report.json lists them.")
      .def_property_readonly(
          "summary", [](const MeshRun& r) { return lines(r.run->result.summary); },
          "The run's figures and what it wrote, a line each: the lines `vorocrust mesh` prints.")
      .def_property_readonly(
          "warnings", [](const MeshRun& r) { return lines(r.run->result.warnings); },
          "Validation's warnings and what the run changed in its input (self-intersections cut, smoothing "
          "rounds refused), a line each.")
      .def_property_readonly(
          "written",
          [](const MeshRun& r) {
            py::list list;
            for (const std::filesystem::path& p : r.run->result.written) list.append(p.string());
            return list;
          },
          "The files and folders written into output_dir, report.json last; empty without output_dir.")
      .def_property_readonly(
          "stop_after", [](const MeshRun& r) { return to_string(r.run->job.options.stop_after); },
          "The last stage the run made: \"balls\", \"surface\" or \"cells\".")
      .def_property_readonly(
          "options",
          [](const MeshRun& r) {
            py::dict d;
            for (const auto& [name, value] : options_in_force(r.run->job.options)) d[py::str(std::string(name))] = python_value(value);
            return d;
          },
          "The options the run used, by name, an unset default resolved (sharp_angle 30, or 60 with smooth).")
      .def(
          "report", [](const MeshRun& r) { return parse_json(job_report_json(r.run->job, r.run->result, 2)); },
          "The run's report as a dict: the document `vorocrust mesh` writes as OUTDIR/report.json (inputs, "
          "options, input description, features, refinement, slivers, surface and its quality, timings).")
      .def(
          "write_report",
          [](const MeshRun& r, const py::object& path) {
            const std::filesystem::path p = to_path(path);
            const std::string text = job_report_json(r.run->job, r.run->result, 2) + "\n";
            py::gil_scoped_release release;
            write_file_atomically(p, text);
          },
          py::arg("path"), "Writes report() as JSON (report.json), atomically.")
      .def(
          "write_quality_svg",
          [](const MeshRun& r, const py::object& path) {
            if (!r.mesh().surface_quality) {
              throw Error(Error::Kind::Usage, "the run stopped before the surface: there is no surface quality to draw");
            }
            const std::filesystem::path p = to_path(path);
            const std::vector<HistogramPanel> panels = quality_panels(r.mesh().surface_quality, r.mesh().cell_quality);
            py::gil_scoped_release release;
            write_histogram_svg(p, "quality: " + (p.parent_path() / "surface.ply").string(), panels);
          },
          py::arg("path"), "Draws the quality histograms (quality.svg), atomically.")
      .def(
          "write_report_html",
          [](const MeshRun& r, const py::object& path) {
            const std::filesystem::path p = to_path(path);
            const ReportPage page = job_report_page(r.run->job, r.run->result);
            py::gil_scoped_release release;
            write_report_html(p, r.mesh(), page);
          },
          py::arg("path"),
          "Writes report.html, atomically: the run's figures, quality tables and pictures in one page that "
          "opens from disk in any browser.")
      .def(
          "cut_picture_png",
          [](const MeshRun& r, int width, int height) {
            std::string png;
            {
              py::gil_scoped_release release;
              png = cut_picture_png(r.mesh(), width, height);
            }
            return py::bytes(png);
          },
          py::arg("width") = 720, py::arg("height") = 540,
          "The cut through the cells that report.html shows, as PNG bytes (cells coloured by material). Raises "
          "UsageError for a run without cells.")
      .def("__repr__", [](const MeshRun& r) {
        const MeshResult& m = r.mesh();
        return "<vorocrust.MeshResult to " + std::string(to_string(r.run->job.options.stop_after)) + ": " +
               std::to_string(m.balls.size()) + " balls, " + std::to_string(m.seeds.size()) + " seeds, " +
               std::to_string(m.surface.num_faces()) + " surface triangles, " + std::to_string(m.cells.cells.size()) +
               " cells>";
      });

  // The table, as `vorocrust options --json` prints it; the boxes' defaults are tuples.
  m.attr("OPTIONS") = parse_json(options_json(Spelling::Python));
  {
    py::list formats;
    for (const OutputFormatSpec& f : output_formats()) {
      py::list files;
      for (std::string_view file : f.files) files.append(std::string(file));
      formats.append(py::make_tuple(std::string(f.name), py::tuple(files), to_string(f.needs), f.volume, std::string(f.help)));
    }
    m.attr("_OUTPUT_TABLE") = formats;
  }
  m.def("_mesh", &run_mesh, py::arg("model"), py::arg("options"), py::arg("output_dir"), py::arg("progress"),
        "The job behind vorocrust.mesh(), which documents the arguments.");
}

}  // namespace vorocrust::python
