// The whole pipeline from Python: vorocrust.mesh() and the MeshResult it returns.
#include <cmath>
#include <limits>

#include "bindings.hpp"
#include "progress_bridge.hpp"

namespace vorocrust::python {
namespace {

Stage stage_named(const std::string& name) {
  if (name == "balls") return Stage::Balls;
  if (name == "surface") return Stage::Surface;
  if (name == "cells") return Stage::Cells;
  throw Error(Error::Kind::Usage, "stop_after must be 'balls', 'surface' or 'cells', got '" + name + "'");
}

InteriorMode interior_named(const std::string& name) {
  for (InteriorMode mode : {InteriorMode::Random, InteriorMode::Lattice, InteriorMode::Cvt}) {
    if (name == to_string(mode)) return mode;
  }
  throw Error(Error::Kind::Usage, "interior must be 'random', 'lattice' or 'cvt', got '" + name + "'");
}

SelfIntersections self_intersections_named(const std::string& name) {
  if (const std::optional<SelfIntersections> mode = parse_self_intersections(name)) return *mode;
  throw Error(Error::Kind::Usage,
              "self_intersections must be 'resolve', 'refuse' or 'keep', got '" + name + "'");
}

const char* stage_name(Stage stage) {
  return stage == Stage::Balls ? "balls" : stage == Stage::Surface ? "surface" : "cells";
}

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
  bool reached(Stage stage) const { return run->options.stop_after >= stage; }

  std::string report(int indent) const {
    RunReport report;
    report.inputs = run->inputs;
    report.options = run->options;
    report.mesh = &run->input;
    report.input = &run->info;
    report.validation = &run->validation;
    report.result = &run->result;
    report.timings = run->result.timings;
    report.status = "ok";
    return run_report_json(report, indent);
  }
};

MeshRun run_mesh(const py::object& model, MeshOptions options, const py::object& progress) {
  options.check();
  const Surface surface = read_surface_input(model);
  auto run = std::make_shared<Run>();
  if (is_path(model)) {
    run->inputs.push_back(to_path(model).string());
  } else if (!py::isinstance<Surface>(model) && py::isinstance<py::list>(model)) {
    for (const py::handle item : model) run->inputs.push_back(to_path(item).string());
  } else {
    run->inputs = source_files(*surface.mesh);
  }
  run->options = options;
  run->input = *surface.mesh;

  ProgressBridge bridge(progress);
  try {
    py::gil_scoped_release release;
    const ThreadLimit threads(options.threads);
    run->validation =
        validate(run->input, {.self_intersections_are_errors = options.self_intersections == SelfIntersections::Refuse});
    for (const Finding& f : run->validation.findings) {
      if (f.severity != Finding::Severity::Error) continue;
      throw Error(Error::Kind::InvalidGeometry,
                  f.message + (f.code == "self-intersection"
                                   ? " (self_intersections=\"resolve\" cuts them along their intersection curves)"
                                   : ""));
    }
    run->info = mesh_info(run->input);
    run->result = generate_mesh(run->input, options, bridge.callback());
  } catch (const Error& e) {
    if (e.kind() == Error::Kind::Cancelled) bridge.rethrow();
    throw;
  }
  return MeshRun{std::move(run), {}, {}, {}, {}, {}, {}};
}

}  // namespace

void bind_mesher(py::module_& m) {
  py::class_<MeshRun>(m, "MeshResult", R"doc(
What one mesh() run made, with everything `vorocrust mesh` writes about it.

Parts the run did not reach are None: `surface` before stop_after="surface", `cells` before
stop_after="cells". Figures (features, refinement, slivers, surface quality) are in report(),
the same document as the CLI's OUTDIR/report.json.
)doc")
      .def_property_readonly(
          "balls",
          [](MeshRun& r) {
            return r.cached(r.balls, [&] { return py::cast(Balls{part_of(r.run, r.run->result.balls)}); });
          },
          "The protecting balls (Balls).")
      .def_property_readonly(
          "seeds",
          [](MeshRun& r) {
            return r.cached(r.seeds, [&]() -> py::object {
              if (!r.reached(Stage::Surface)) return py::none();
              return py::cast(Seeds{part_of(r.run, r.run->result.seeds)});
            });
          },
          "The seeds (Seeds): surface seeds first, two per seed pair, then interior and outside seeds "
          "once the run reaches the cells; None before stop_after=\"surface\".")
      .def_property_readonly(
          "surface",
          [](MeshRun& r) {
            return r.cached(r.surface, [&]() -> py::object {
              if (!r.reached(Stage::Surface)) return py::none();
              return py::cast(Surface{part_of(r.run, r.run->result.surface)});
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
              return py::cast(make_cells(part_of(r.run, r.run->result.cells)));
            });
          },
          "The conforming Voronoi mesh (Cells) of the material seeds; None before stop_after=\"cells\".")
      .def_property_readonly(
          "input",
          [](MeshRun& r) {
            return r.cached(r.input, [&] { return py::cast(Surface{part_of(r.run, r.run->input)}); });
          },
          "The input surface as meshed: validated, its orientation fixed.")
      .def_property_readonly(
          "smoothed_input",
          [](MeshRun& r) {
            return r.cached(r.smoothed_input,
                            [&] { return py::cast(Surface{part_of(r.run, r.run->result.smoothed_input)}); });
          },
          "The surface the balls cover: the input after patch smoothing (the input itself without it).")
      .def_property_readonly(
          "validation", [](const MeshRun& r) { return findings_list(r.run->validation); },
          "The input validation's findings, as validate() gives them.")
      .def_property_readonly(
          "surface_quality",
          [](const MeshRun& r) -> py::object {
            if (!r.run->result.surface_quality) return py::none();
            return parse_json(surface_quality_json(*r.run->result.surface_quality));
          },
          "The output surface measured against the input (dict, as measure_surface_quality()), or None.")
      .def_property_readonly(
          "timings",
          [](const MeshRun& r) {
            py::list list;
            for (const PhaseTiming& t : r.run->result.timings) list.append(py::make_tuple(t.name, t.seconds));
            return list;
          },
          "(phase, seconds) for every phase of the run.")
      .def_property_readonly(
          "stop_after", [](const MeshRun& r) { return stage_name(r.run->options.stop_after); },
          "The last stage the run made: \"balls\", \"surface\" or \"cells\".")
      .def(
          "report", [](const MeshRun& r) { return parse_json(r.report(2)); },
          "The run's report as a dict: the document `vorocrust mesh` writes as OUTDIR/report.json (inputs, "
          "options, input description, features, refinement, slivers, surface and its quality, timings).")
      .def(
          "write_report",
          [](const MeshRun& r, const py::object& path) {
            const std::filesystem::path p = to_path(path);
            const std::string text = r.report(2) + "\n";
            py::gil_scoped_release release;
            write_file_atomically(p, text);
          },
          py::arg("path"), "Writes report() as JSON (report.json), atomically.")
      .def(
          "write_quality_svg",
          [](const MeshRun& r, const py::object& path) {
            if (!r.run->result.surface_quality) {
              throw Error(Error::Kind::Usage, "the run stopped before the surface: there is no surface quality to draw");
            }
            const std::filesystem::path p = to_path(path);
            py::gil_scoped_release release;
            write_histogram_svg(p, "surface quality: " + (p.parent_path() / "surface.ply").string(),
                                {surface_quality_panel(*r.run->result.surface_quality)});
          },
          py::arg("path"), "Draws the output surface's triangle-quality histogram (quality.svg), atomically.")
      .def("__repr__", [](const MeshRun& r) {
        const MeshResult& m = r.run->result;
        return "<vorocrust.MeshResult to " + std::string(stage_name(r.run->options.stop_after)) + ": " +
               std::to_string(m.balls.size()) + " balls, " + std::to_string(m.seeds.size()) + " seeds, " +
               std::to_string(m.surface.num_faces()) + " surface triangles, " + std::to_string(m.cells.cells.size()) +
               " cells>";
      });

  {
    // The library's defaults, so mesh() and the add-ons offer the same ones.
    const MeshOptions defaults;
    py::dict d;
    d["lipschitz"] = defaults.lipschitz;
    d["smooth"] = defaults.smooth;
    d["sharp_angle"] = defaults.sharp_angle();  // with smooth=False; mesh() takes None for the mode's own
    d["smoothing_iterations"] = defaults.smoothing_rounds();
    d["smooth_sharp_angle"] = MeshOptions::kSmoothSharpAngleDegrees;
    d["smooth_smoothing_iterations"] = MeshOptions::kSmoothSmoothingIterations;
    d["smoothing_tolerance"] = defaults.smoothing_tolerance;
    d["min_triangle_angle"] = defaults.min_triangle_angle();
    d["smooth_min_triangle_angle"] = MeshOptions::kSmoothMinTriangleAngleDegrees;
    d["interior"] = to_string(defaults.interior);
    d["cvt_iterations"] = defaults.cvt_iterations;
    d["max_aspect_ratio"] = defaults.max_aspect_ratio;
    d["stop_after"] = stage_name(defaults.stop_after);
    d["seed"] = defaults.seed;
    d["threads"] = defaults.threads;
    d["self_intersections"] = to_string(defaults.self_intersections);
    m.attr("DEFAULT_OPTIONS") = d;
  }
  m.def(
      "_mesh",
      [](const py::object& model, double lipschitz, bool smooth, const std::optional<double>& sharp_angle,
         const py::object& max_size, const py::object& sizing, const std::optional<int>& smoothing_iterations,
         double smoothing_tolerance,
         const std::optional<double>& min_triangle_angle, const std::string& interior, int cvt_iterations,
         double max_aspect_ratio, const std::string& stop_after, std::uint64_t seed, int threads, const std::string& self_intersections,
         const std::optional<std::array<double, 6>>& box, const py::object& progress) {
        MeshOptions options;
        options.lipschitz = lipschitz;
        options.smooth = smooth;
        options.sharp_angle_degrees = sharp_angle;
        options.max_size = max_size.is_none() ? std::numeric_limits<double>::infinity() : max_size.cast<double>();
        if (!sizing.is_none()) options.sizing_file = to_path(sizing);
        options.smoothing_iterations = smoothing_iterations;
        options.smoothing_tolerance = smoothing_tolerance;
        options.min_triangle_angle_degrees = min_triangle_angle;
        options.interior = interior_named(interior);
        options.cvt_iterations = cvt_iterations;
        options.max_aspect_ratio = max_aspect_ratio;
        options.stop_after = stage_named(stop_after);
        options.seed = seed;
        options.threads = threads;
        options.box = box;
        options.self_intersections = self_intersections_named(self_intersections);
        return run_mesh(model, options, progress);
      },
      py::arg("model"), py::arg("lipschitz"), py::arg("smooth"), py::arg("sharp_angle"), py::arg("max_size"),
      py::arg("sizing"),
      py::arg("smoothing_iterations"), py::arg("smoothing_tolerance"), py::arg("min_triangle_angle"), py::arg("interior"), py::arg("cvt_iterations"),
      py::arg("max_aspect_ratio"), py::arg("stop_after"),
      py::arg("seed"), py::arg("threads"), py::arg("self_intersections"), py::arg("box"), py::arg("progress"),
      "The pipeline behind vorocrust.mesh(), which documents the arguments.");
}

}  // namespace vorocrust::python
