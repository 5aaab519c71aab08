// Seeds (paper 2.4, 2.5) and the protecting balls (2.3): arrays out, arrays in, files.
#include <algorithm>
#include <cstdint>
#include <optional>

#include "bindings.hpp"

namespace vorocrust::python {
namespace {

constexpr StratumType kStratumTypes[] = {StratumType::Corner, StratumType::Crease, StratumType::Patch};

SeedKind seed_kind(const std::string& name) {
  if (const std::optional<SeedKind> kind = seed_kind_named(name)) return *kind;
  throw Error(Error::Kind::Usage, "unknown seed kind '" + name + "': expected " + seed_kind_names());
}

// Seeds from arrays: positions n x 3, labels n; radii and kinds optional.
Seeds seeds_from_arrays(const py::object& positions, const py::object& labels, const py::object& radii,
                        const py::object& kinds) {
  const auto p = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(positions);
  // Labels as 64-bit integers (any integer array casts safely), then checked against 32 bits.
  const auto l = py::array_t<std::int64_t, py::array::c_style>::ensure(labels);
  if (!p || p.ndim() != 2 || p.shape(1) != 3) throw Error(Error::Kind::Usage, "seed positions must be an n x 3 array");
  const std::size_t n = static_cast<std::size_t>(p.shape(0));
  if (!l || l.ndim() != 1 || static_cast<std::size_t>(l.shape(0)) != n) {
    throw Error(Error::Kind::Usage, "seed labels must be n integers, one per position");
  }
  const bool has_radii = !radii.is_none();
  py::array_t<double, py::array::c_style | py::array::forcecast> r;
  if (has_radii) {
    r = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(radii);
    if (!r || r.ndim() != 1 || static_cast<std::size_t>(r.shape(0)) != n) {
      throw Error(Error::Kind::Usage, "seed radii must be n numbers, one per position");
    }
  }
  std::vector<std::string> kind_names;
  if (!kinds.is_none()) {
    for (const py::handle k : kinds) kind_names.push_back(py::str(k));
    if (kind_names.size() != n) throw Error(Error::Kind::Usage, "seed kinds must be n names, one per position");
  }
  auto seeds = std::make_shared<std::vector<Seed>>(n);
  for (std::size_t i = 0; i < n; ++i) {
    Seed& s = (*seeds)[i];
    s.position = Point(p.at(i, 0), p.at(i, 1), p.at(i, 2));
    if (l.at(i) < INT32_MIN || l.at(i) > INT32_MAX) {
      throw Error(Error::Kind::Usage, "seed " + std::to_string(i) + " has label " + std::to_string(l.at(i)) +
                                          ", out of the 32-bit range");
    }
    s.region = static_cast<std::int32_t>(l.at(i));
    s.radius = has_radii ? r.at(i) : 0.0;
    s.kind = kinds.is_none() ? (s.region == kOutsideRegion ? SeedKind::Outside : SeedKind::Interior)
                             : seed_kind(kind_names[i]);
  }
  return {std::move(seeds)};
}

}  // namespace

void bind_seeds(py::module_& m) {
  py::class_<Seeds>(m, "Seeds", R"doc(
Voronoi seeds with their labels: the whole mesh in compact form (the cells follow from them).

Seeds(positions, labels, radii=None, kinds=None) builds a set from an n x 3 array of
positions and n integer labels (regions: 0 is outside, 1, 2, ... are materials); radii default
to 0, kinds ("surface", "interior", "outside", "cap", "repair") to "outside" for label 0 and "interior" else.
Arrays are read-only copies; a Seeds never changes once made.
)doc")
      .def(py::init(&seeds_from_arrays), py::arg("positions"), py::arg("labels"), py::arg("radii") = py::none(),
           py::arg("kinds") = py::none())
      .def_property_readonly(
          "positions", [](const Seeds& s) { return point_rows(*s.seeds, [](const Seed& x) { return x.position; }); },
          "Seed positions, float64, n x 3.")
      .def_property_readonly(
          "labels", [](const Seeds& s) { return column<std::int32_t>(*s.seeds, [](const Seed& x) { return x.region; }); },
          "Region of each seed, int32: 0 outside, 1, 2, ... materials.")
      .def_property_readonly(
          "radii", [](const Seeds& s) { return column<double>(*s.seeds, [](const Seed& x) { return x.radius; }); },
          "Radius of each seed's ball, float64 (surface seeds: the mean radius of their three balls).")
      .def_property_readonly(
          "kinds",
          [](const Seeds& s) {
            py::list names;
            for (const Seed& x : *s.seeds) names.append(to_string(x.kind));
            return read_only(py::module_::import("numpy").attr("array")(names, "U8"));
          },
          "Kind of each seed as a string array: \"surface\", \"interior\" or \"outside\".")
      .def("__len__", [](const Seeds& s) { return s.seeds->size(); })
      .def("__repr__", [](const Seeds& s) {
        std::size_t counts[3] = {0, 0, 0};
        for (const Seed& x : *s.seeds) ++counts[static_cast<int>(x.kind)];
        return "<vorocrust.Seeds: " + std::to_string(s.seeds->size()) + " (" + std::to_string(counts[0]) +
               " surface, " + std::to_string(counts[1]) + " interior, " + std::to_string(counts[2]) + " outside)>";
      });

  m.def(
      "read_seeds",
      [](const py::object& path) {
        const std::filesystem::path p = to_path(path);
        py::gil_scoped_release release;
        return Seeds{std::make_shared<const std::vector<Seed>>(read_seeds_csv(p))};
      },
      py::arg("path"), R"doc(
Reads a seeds.csv as `vorocrust mesh` writes it (x,y,z,label,radius,kind). Raises
UnreadableInputError naming the file and line of the first bad line.
)doc");
  def_writer<Seeds>(
      m, "write_seeds", "seeds", "path", [](const Seeds& s, const auto& p) { write_seeds_csv(*s.seeds, p); }, R"doc(
Writes seeds.csv (x,y,z,label,radius,kind; 17 significant digits) atomically, as
`vorocrust mesh` does; `vorocrust cells` and compute_cells() rebuild the mesh from it.
)doc");

  py::class_<Balls> balls(m, "Balls", R"doc(
The protecting and covering balls of the refinement (paper 2.3), centred on the input surface.
Arrays are read-only copies; Balls.type_names names the stratum types by their number in
`types` ("corner", "crease", "patch").
)doc");
  py::tuple type_names(std::size(kStratumTypes));
  for (std::size_t i = 0; i < std::size(kStratumTypes); ++i) type_names[i] = to_string(kStratumTypes[i]);
  balls.attr("type_names") = type_names;  // the names of the numbers in `types`
  balls.def_property_readonly(
          "centers", [](const Balls& b) { return point_rows(*b.balls, [](const Ball& x) { return x.center; }); },
          "Ball centres, float64, n x 3.")
      .def_property_readonly(
          "radii", [](const Balls& b) { return column<double>(*b.balls, [](const Ball& x) { return x.radius; }); },
          "Ball radii, float64.")
      .def_property_readonly(
          "types",
          [](const Balls& b) {
            return column<std::uint8_t>(*b.balls, [](const Ball& x) { return static_cast<std::uint8_t>(x.type); });
          },
          "Stratum type of each ball, uint8: 0 corner, 1 crease, 2 patch (names in `type_names`).")
      .def_property_readonly(
          "strata", [](const Balls& b) { return column<std::uint32_t>(*b.balls, [](const Ball& x) { return x.stratum; }); },
          "The corner, crease or patch number of each ball, uint32.")
      .def("__len__", [](const Balls& b) { return b.balls->size(); })
      .def("__repr__", [](const Balls& b) { return "<vorocrust.Balls: " + std::to_string(b.balls->size()) + ">"; });

  def_writer<Balls>(
      m, "write_balls", "balls", "path",
      [](const Balls& b, const std::filesystem::path& p) {
        if (p.extension() == ".vtk") {
          write_balls_vtk(*b.balls, p);
        } else if (p.extension() == ".csv") {
          write_balls_csv(*b.balls, p);
        } else {
          throw Error(Error::Kind::Usage, "balls are written as .csv or .vtk, not '" + p.extension().string() + "'",
                      {.file = p.string()});
        }
      },
      R"doc(
Writes the balls as balls.csv (x,y,z,radius,stratum_type,stratum_index) or, for a .vtk path, a
VTK polydata file of the centres with radius, type and stratum (glyph by radius in ParaView).
)doc");
}

}  // namespace vorocrust::python
