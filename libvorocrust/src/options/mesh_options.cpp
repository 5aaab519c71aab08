// The table of a mesh run's options: every option once, with its default, range and help.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iterator>

#include "core/c_format.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/options.hpp"

namespace vorocrust {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Pieces appended in turn: GCC 12 warns (-Wrestrict, falsely) of "literal" + std::string.
std::string concat(std::initializer_list<std::string_view> pieces) {
  std::string out;
  for (std::string_view piece : pieces) out += piece;
  return out;
}

std::vector<std::string> format_names(const std::vector<OutputFormat>& formats) {
  std::vector<std::string> names;
  for (OutputFormat f : formats) names.emplace_back(to_string(f));
  return names;
}

std::vector<OutputFormat> formats_named(const std::vector<std::string>& names) {
  std::vector<OutputFormat> formats;
  for (const OutputFormatSpec& f : output_formats()) {
    if (std::find(names.begin(), names.end(), f.name) != names.end()) formats.push_back(f.format);
  }
  return formats;
}

template <class Enum>
Enum choice_of(const OptionValue& v) {
  return *parse_choice<Enum>(std::get<std::string>(v));
}

template <class T>
OptionValue optional_number(const std::optional<T>& x) {
  if (!x) return std::monostate{};
  if constexpr (std::is_integral_v<T>) {
    return static_cast<std::int64_t>(*x);
  } else {
    return static_cast<double>(*x);
  }
}

// A bound that is infinite until given: unset in the table.
template <double MeshOptions::*bound>
OptionValue get_bound(const MeshOptions& o) {
  if (std::isinf(o.*bound)) return std::monostate{};
  return o.*bound;
}
template <double MeshOptions::*bound>
void set_bound(MeshOptions& o, const OptionValue& v) {
  o.*bound = v.index() == 0 ? kInf : std::get<double>(v);
}

// A file that is none until given: unset in the table.
template <std::filesystem::path MeshOptions::*file>
OptionValue get_file(const MeshOptions& o) {
  if ((o.*file).empty()) return std::monostate{};
  return (o.*file).string();
}
template <std::filesystem::path MeshOptions::*file>
void set_file(MeshOptions& o, const OptionValue& v) {
  o.*file = v.index() == 0 ? std::filesystem::path() : std::filesystem::path(std::get<std::string>(v));
}

// The table. Help texts say what an option does in the paper's words and name no flag: each front
// end adds its own spelling, the default and the range (default_text, range_text).
const std::array<OptionSpec, 23> kSpecs = {{
    {.name = "lipschitz",
     .kind = OptionKind::Real,
     .label = "Lipschitz constant L",
     .help = "How fast ball radii may vary along the surface: a smaller L gives more, more evenly sized "
             "balls and cells",
     .section = "2.1",
     .group = "Surface",
     .default_value = 0.25,
     .min = 0,
     .max = 1,
     .min_open = true,
     .max_open = true,
     .get = [](const MeshOptions& o) -> OptionValue { return o.lipschitz; },
     .set = [](MeshOptions& o, const OptionValue& v) { o.lipschitz = std::get<double>(v); }},
    {.name = "smooth",
     .kind = OptionKind::Flag,
     .label = "Smooth surface",
     .help = "The input approximates a smooth surface (a scan, a coarse tessellation of a curved shape): it is "
             "smoothed as one patch (boundary and non-manifold edges stay) and its features are found on the "
             "result, so the folds of its tessellation are not creases. Sets the defaults of `sharp_angle` to 60, "
             "`smoothing_iterations` to 6 and `min_triangle_angle` to 30, the paper's settings for smooth models",
     .section = "2.2",
     .group = "Surface",
     .default_value = false,
     .get = [](const MeshOptions& o) -> OptionValue { return o.smooth; },
     .set = [](MeshOptions& o, const OptionValue& v) { o.smooth = std::get<bool>(v); }},
    {.name = "sharp_angle",
     .kind = OptionKind::Real,
     .label = "Sharp angle",
     .help = "theta#: an edge whose two faces' normals differ by more than this is a sharp crease, kept exactly, "
             "and normals may turn by at most this much between co-smooth points. 30 keeps every crease of CAD "
             "models while the tessellation rings of curved surfaces stay smooth",
     .section = "2.2",
     .unit = "degrees",
     .group = "Surface",
     .default_value = std::monostate{},
     .min = 0,
     .max = 90,
     .min_open = true,
     .max_open = true,
     .plain_default = MeshOptions::kSharpAngleDegrees,
     .smooth_default = MeshOptions::kSmoothSharpAngleDegrees,
     .unset_number = 0,
     .get = [](const MeshOptions& o) { return optional_number(o.sharp_angle_degrees); },
     .set =
         [](MeshOptions& o, const OptionValue& v) {
           o.sharp_angle_degrees = v.index() == 0 ? std::nullopt : std::optional(std::get<double>(v));
         }},
    {.name = "max_size",
     .kind = OptionKind::Real,
     .label = "Maximum size",
     .help = "A uniform bound on ball radii and cell sizes",
     .section = "2.1",
     .group = "Surface",
     .default_value = std::monostate{},
     .min = 0,
     .max = kInf,
     .min_open = true,
     .unset_means = "no bound",
     .unset_number = 0,
     .get = get_bound<&MeshOptions::max_size>,
     .set = set_bound<&MeshOptions::max_size>},
    {.name = "sizing",
     .kind = OptionKind::File,
     .label = "Sizing file",
     .help = "A spatially varying bound on ball radii: a text file of lines 'x y z size' ('#' starts a comment); "
             "the size at a point is the inverse-distance-weighted mean of the 8 nearest given points, never above "
             "`max_size`",
     .section = "2.1",
     .group = "Surface",
     .default_value = std::monostate{},
     .unset_means = "none",
     .get = get_file<&MeshOptions::sizing_file>,
     .set = set_file<&MeshOptions::sizing_file>},
    {.name = "smoothing_iterations",
     .kind = OptionKind::Integer,
     .label = "Smoothing iterations",
     .help = "Rounds of adaptive Loop subdivision inside smooth patches before refinement, at most: fewer are "
             "applied when more would make a sharp feature or carry the surface through itself",
     .section = "2.2",
     .group = "Surface",
     .default_value = std::monostate{},
     .min = 0,
     .max = 20,
     .plain_default = 0,
     .smooth_default = MeshOptions::kSmoothSmoothingIterations,
     .unset_number = -1,
     .get = [](const MeshOptions& o) { return optional_number(o.smoothing_iterations); },
     .set =
         [](MeshOptions& o, const OptionValue& v) {
           o.smoothing_iterations =
               v.index() == 0 ? std::nullopt : std::optional(static_cast<int>(std::get<std::int64_t>(v)));
         }},
    {.name = "smoothing_tolerance",
     .kind = OptionKind::Real,
     .label = "Smoothing tolerance",
     .help = "How far smoothing should move the surface at most, as a fraction of the input's bounding-box "
             "diagonal (a target): the faces around a vertex that Loop's rules would move farther are first split "
             "at their edge midpoints, at most twice; 0: Loop's rules alone, as the paper smooths",
     .section = "2.2",
     .group = "Surface",
     .default_value = MeshOptions::kDefaultSmoothingTolerance,
     .min = 0,
     .max = kInf,
     .max_open = true,
     .get = [](const MeshOptions& o) -> OptionValue { return o.smoothing_tolerance; },
     .set = [](MeshOptions& o, const OptionValue& v) { o.smoothing_tolerance = std::get<double>(v); }},
    {.name = "min_triangle_angle",
     .kind = OptionKind::Real,
     .label = "Smallest triangle angle",
     .help = "Surface triangles away from creases and corners with an angle below this are split by shrinking the "
             "balls that cover their circumcentres; 0 splits none",
     .section = "2.4",
     .unit = "degrees",
     .group = "Surface",
     .default_value = std::monostate{},
     .min = 0,
     .max = MeshOptions::kMaxMinTriangleAngleDegrees,
     .plain_default = 0,
     .smooth_default = MeshOptions::kSmoothMinTriangleAngleDegrees,
     .unset_number = -1,
     .get = [](const MeshOptions& o) { return optional_number(o.min_triangle_angle_degrees); },
     .set =
         [](MeshOptions& o, const OptionValue& v) {
           o.min_triangle_angle_degrees = v.index() == 0 ? std::nullopt : std::optional(std::get<double>(v));
         }},
    {.name = "box",
     .kind = OptionKind::Box,
     .label = "Domain box",
     .help = "The domain around open sheets (terrains, faults, horizons): xmin ymin zmin xmax ymax zmax. Its sides "
             "join the surface, and what no material fills inside it becomes the material 'domain', which a sheet "
             "splits",
     .section = "3",
     .group = "Domain",
     .default_value = std::monostate{},
     .unset_means = "for an input with open edges, its bounding box grown by a tenth of its diagonal on every side; "
                    "none for a closed input",
     .get =
         [](const MeshOptions& o) -> OptionValue {
           if (!o.box) return std::monostate{};
           return *o.box;
         },
     .set =
         [](MeshOptions& o, const OptionValue& v) {
           o.box = v.index() == 0 ? std::nullopt : std::optional(std::get<std::array<double, 6>>(v));
         }},
    {.name = "self_intersections",
     .kind = OptionKind::Choice,
     .label = "Self-intersections",
     .help = "Faces that cut through each other: 'resolve' cuts them along their intersection curves, which become "
             "creases, and joins each new piece of space to a region of the input; 'refuse' stops the run naming "
             "them; 'keep' meshes them as they are",
     .section = "3",
     .group = "Domain",
     .default_value = std::string("resolve"),
     .choices = choice_names<SelfIntersections>(),
     .get = [](const MeshOptions& o) -> OptionValue { return std::string(to_string(o.self_intersections)); },
     .set =
         [](MeshOptions& o, const OptionValue& v) { o.self_intersections = choice_of<SelfIntersections>(v); }},
    {.name = "method",
     .kind = OptionKind::Choice,
     .label = "Method",
     .help = "How the cells meet the surface: 'vorocrust' (seeds in pairs about the surface; every cell a whole, "
             "convex Voronoi cell, the surface approximated by their faces) or 'clipped' (seeds inside only, each "
             "Voronoi cell cut to its material's region: the boundary, the interfaces and the volumes exact, the cut "
             "cells not convex; "
             "`interior` 'random' gives Ebeida and Mitchell's maximal Poisson-disk seeds of radius `max_size` "
             "(unset, a twentieth of the input's diagonal), 'cvt' Yan et al.'s Lloyd iterations on the clipped "
             "cells, the seeds of the cells on the surface moved onto it for the second half, 'lattice' a cubic "
             "lattice of that spacing)",
     .section = "1",
     .group = "Domain",
     .default_value = std::string("vorocrust"),
     .choices = choice_names<Method>(),
     .get = [](const MeshOptions& o) -> OptionValue { return std::string(to_string(o.method)); },
     .set = [](MeshOptions& o, const OptionValue& v) { o.method = choice_of<Method>(v); }},
    {.name = "interior",
     .kind = OptionKind::Choice,
     .label = "Interior seeds",
     .help = "How the volume away from the surface is seeded: 'random' (Poisson-disk, graded from the surface "
             "inward), 'lattice' (cubic, hex-dominant cells), 'cvt' (random, then Lloyd iterations)",
     .section = "2.5",
     .group = "Interior",
     .default_value = std::string("random"),
     .choices = choice_names<InteriorMode>(),
     .get = [](const MeshOptions& o) -> OptionValue { return std::string(to_string(o.interior)); },
     .set = [](MeshOptions& o, const OptionValue& v) { o.interior = choice_of<InteriorMode>(v); }},
    {.name = "cvt_iterations",
     .kind = OptionKind::Integer,
     .label = "CVT iterations",
     .help = "Lloyd iterations of the 'cvt' `interior`",
     .section = "2.5",
     .group = "Interior",
     .default_value = std::int64_t{20},
     .min = 0,
     .max = 10000,
     .get = [](const MeshOptions& o) -> OptionValue { return std::int64_t{o.cvt_iterations}; },
     .set =
         [](MeshOptions& o, const OptionValue& v) { o.cvt_iterations = static_cast<int>(std::get<std::int64_t>(v)); }},
    {.name = "sliver_angle",
     .kind = OptionKind::Real,
     .label = "Sliver angle of the dual tetrahedra",
     .help = "With `method` 'clipped': seeds of the dual tetrahedra (tets.vtu) with a dihedral angle below this many "
             "degrees move a little at random, each move kept where the tetrahedra about it come out better (Yan et "
             "al.'s sliver perturbation, best after `interior` 'cvt'); the cells stay exact clipped Voronoi cells of "
             "the moved seeds; 0 moves none",
     .section = "1",
     .group = "Interior",
     .default_value = 0.0,
     .min = 0,
     .max = 45,
     .max_open = true,
     .get = [](const MeshOptions& o) -> OptionValue { return o.sliver_angle; },
     .set = [](MeshOptions& o, const OptionValue& v) { o.sliver_angle = std::get<double>(v); }},
    {.name = "weld",
     .kind = OptionKind::Real,
     .label = "Weld short edges",
     .help = "With `method` 'clipped': edges shorter than this fraction of the seeds' radius collapse to one point "
             "(Ebeida and Mitchell's welding; theirs is 1e-4), the faces about them left slightly non-planar and "
             "their largest non-planarity reported; 0 welds none",
     .section = "1",
     .group = "Domain",
     .default_value = 0.0,
     .min = 0,
     .max = 0.5,
     .max_open = true,
     .get = [](const MeshOptions& o) -> OptionValue { return o.weld; },
     .set = [](MeshOptions& o, const OptionValue& v) { o.weld = std::get<double>(v); }},
    {.name = "seeds",
     .kind = OptionKind::File,
     .label = "Seeds file",
     .help = "With `method` 'clipped': the seeds, a CSV file as OUTDIR/seeds.csv is written (x,y,z,label,radius,kind), "
             "instead of sampled ones; each seed of a material must lie in its region, outside seeds (label 0) are "
             "ignored, and `interior` 'cvt' moves them by Lloyd iterations; each moves by at most a thousandth of the "
             "distance to its nearest, as the lattice's points do, so that a grid's ties with the input's faces go",
     .section = "1",
     .group = "Domain",
     .default_value = std::monostate{},
     .unset_means = "none",
     .get = get_file<&MeshOptions::seeds_file>,
     .set = set_file<&MeshOptions::seeds_file>},
    {.name = "max_aspect_ratio",
     .kind = OptionKind::Real,
     .label = "Largest cell aspect ratio",
     .help = "Cells whose aspect ratio (enclosing sphere over inscribed ball) exceeds this get a seed at their "
             "centroid, for at most two rounds",
     .section = "3",
     .group = "Interior",
     .default_value = MeshOptions::kDefaultMaxAspectRatio,
     .min = MeshOptions::kLowestMaxAspectRatio,
     .max = kInf,
     .max_open = true,
     .also = 0,
     .also_means = "no splits",
     .get = [](const MeshOptions& o) -> OptionValue { return o.max_aspect_ratio; },
     .set = [](MeshOptions& o, const OptionValue& v) { o.max_aspect_ratio = std::get<double>(v); }},
    {.name = "max_skewness",
     .kind = OptionKind::Real,
     .label = "Largest face skewness",
     .help = "Faces between two cells more skew than this (as checkMesh measures skewness) get a seed that "
             "repairs them, for as long as the count of such faces falls",
     .section = "3",
     .group = "Interior",
     .default_value = MeshOptions::kDefaultMaxSkewness,
     .min = 0,
     .max = kInf,
     .min_open = true,
     .max_open = true,
     .get = [](const MeshOptions& o) -> OptionValue { return o.max_skewness; },
     .set = [](MeshOptions& o, const OptionValue& v) { o.max_skewness = std::get<double>(v); }},
    {.name = "stop_after",
     .kind = OptionKind::Choice,
     .label = "Stop after",
     .help = "The last stage to run: 'balls' (the protecting balls), 'surface' (also the surface seeds and the "
             "surface mesh), 'cells' (the whole Voronoi mesh)",
     .group = "Run",
     .default_value = std::string("cells"),
     .choices = choice_names<Stage>(),
     .get = [](const MeshOptions& o) -> OptionValue { return std::string(to_string(o.stop_after)); },
     .set = [](MeshOptions& o, const OptionValue& v) { o.stop_after = choice_of<Stage>(v); }},
    {.name = "seed",
     .kind = OptionKind::Integer,
     .label = "Random seed",
     .help = "Equal input, options and seed give equal output, whatever the number of threads",
     .group = "Run",
     .default_value = std::int64_t{0},
     .min = 0,
     .max = static_cast<double>(MeshOptions::kMaxSeed),
     .get = [](const MeshOptions& o) -> OptionValue { return static_cast<std::int64_t>(o.seed); },
     .set = [](MeshOptions& o, const OptionValue& v) { o.seed = static_cast<std::uint64_t>(std::get<std::int64_t>(v)); }},
    {.name = "threads",
     .kind = OptionKind::Integer,
     .label = "Threads",
     .help = "Worker threads, 0 for all cores; the results do not depend on it",
     .group = "Run",
     .default_value = std::int64_t{0},
     .min = 0,
     .max = 4096,
     .get = [](const MeshOptions& o) -> OptionValue { return std::int64_t{o.threads}; },
     .set = [](MeshOptions& o, const OptionValue& v) { o.threads = static_cast<int>(std::get<std::int64_t>(v)); }},
    {.name = "max_memory",
     .kind = OptionKind::Real,
     .label = "Memory bound",
     .help = "Refuse a run whose estimated peak memory exceeds this many gigabytes: before the surface stages, when "
             "`max_size` asks for more cells than this holds (unset, the machine's memory); while its interior seeds "
             "are placed, as soon as those placed so far need more; and once all are placed, before its cells are "
             "cut; the message gives the estimate",
     .unit = "GB",
     .group = "Run",
     .default_value = std::monostate{},
     .min = 0,
     .max = kInf,
     .min_open = true,
     .unset_means = "no bound",
     .unset_number = 0,
     .get = get_bound<&MeshOptions::max_memory_gb>,
     .set = set_bound<&MeshOptions::max_memory_gb>},
    {.name = "formats",
     .kind = OptionKind::Choices,
     .label = "Outputs",
     .help = "What to write into the output folder: vtu (mesh.vtu), openfoam (case/), tough (MESH), pflotran "
             "(pflotran/), exodus (mesh.exo), tets (tets.vtu, the dual tetrahedra of a clipped mesh), seeds (seeds.csv), "
             "obj and ply (the surface), balls (balls.csv, balls.vtk, smoothed_surface.ply), svg (quality.svg), html "
             "(report.html); report.json is always written",
     .group = "Outputs",
     .default_value = std::vector<std::string>(choice_names<OutputFormat>().begin(), choice_names<OutputFormat>().end()),
     .choices = choice_names<OutputFormat>(),
     .cli_alias = "--format",
     .get = [](const MeshOptions& o) -> OptionValue { return format_names(o.formats); },
     .set = [](MeshOptions& o, const OptionValue& v) { o.formats = formats_named(std::get<std::vector<std::string>>(v)); }},
}};

[[noreturn]] void refuse(const OptionSpec& spec, const std::string& why) {
  throw Error(Error::Kind::Usage, std::string(spec.name) + " " + why, {.option = std::string(spec.name)});
}

std::string number_text(double x) {
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return c_format("%.10g", x);
}

bool in_range(const OptionSpec& spec, double x) {
  if (spec.also && x == *spec.also) return true;
  if (std::isnan(x)) return false;
  const bool above = spec.min_open ? x > spec.min : x >= spec.min;
  const bool below = spec.max_open ? x < spec.max : x <= spec.max;
  return above && below;
}

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

std::optional<double> real_from(std::string_view text) {
  text = trimmed(text);
  double x = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return x;
}

std::vector<std::string_view> words(std::string_view text, char separator) {
  std::vector<std::string_view> out;
  while (true) {
    const std::size_t at = text.find(separator);
    const std::string_view word = trimmed(text.substr(0, at));
    if (!word.empty()) out.push_back(word);
    if (at == std::string_view::npos) break;
    text.remove_prefix(at + 1);
  }
  return out;
}

std::string choices_text(const OptionSpec& spec) {
  std::string text;
  for (std::size_t k = 0; k < spec.choices.size(); ++k) {
    if (k > 0) text += k + 1 == spec.choices.size() ? " or " : ", ";
    text += spec.choices[k];
  }
  return text;
}

// "must lie between 0 and 1", "must be at least 3, or 0 (no splits)": what a value out of range
// is told.
std::string must(const OptionSpec& spec) {
  const std::string range = range_text(spec);
  return (range.find("between") != std::string::npos ? "must lie " : "must be ") + range;
}

bool is_choice(const OptionSpec& spec, std::string_view name) {
  return std::find(spec.choices.begin(), spec.choices.end(), name) != spec.choices.end();
}

}  // namespace

std::span<const OptionSpec> mesh_option_specs() noexcept { return kSpecs; }

const OptionSpec* find_option(std::string_view name) noexcept {
  for (const OptionSpec& spec : kSpecs) {
    if (spec.name == name) return &spec;
  }
  return nullptr;
}

std::vector<OutputFormat> MeshOptions::all_output_formats() {
  std::vector<OutputFormat> all;
  for (const OutputFormatSpec& f : output_formats()) all.push_back(f.format);
  return all;
}

std::string option_spelling(const OptionSpec& spec, Spelling spelling) {
  if (spelling == Spelling::Label) return concat({"\"", spec.label, "\""});
  std::string out;
  bool upper = spelling == Spelling::FreeCad;
  if (spelling == Spelling::Cli) out = "--";
  for (char c : spec.name) {
    if (c == '_') {
      if (spelling == Spelling::Python) out += '_';
      if (spelling == Spelling::Cli) out += '-';
      upper = spelling == Spelling::MeshLab || spelling == Spelling::FreeCad;
      continue;
    }
    out += upper ? static_cast<char>(c - 'a' + 'A') : c;
    upper = false;
  }
  return out;
}

namespace {

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; }

// `text` with the whole-word occurrences of `name` replaced by `spelled`.
std::string replace_word(const std::string& text, const std::string& name, const std::string& spelled) {
  std::string out;
  std::size_t at = 0;
  while (true) {
    const std::size_t found = text.find(name, at);
    if (found == std::string::npos) break;
    const bool starts = found == 0 || !word_char(text[found - 1]);
    const bool ends = found + name.size() == text.size() || !word_char(text[found + name.size()]);
    out.append(text, at, found - at);
    out += starts && ends ? spelled : name;
    at = found + name.size();
  }
  out.append(text, at);
  return out;
}

}  // namespace

std::string spell_options(const std::string& text, Spelling spelling) {
  std::string out = text;
  for (const OptionSpec& spec : kSpecs) {
    out = replace_word(out, concat({"`", spec.name, "`"}), option_spelling(spec, spelling));
  }
  return out;
}

std::string spelled_message(const std::string& message, const std::string& option, Spelling spelling) {
  // The option at fault by its bare name, any other in backquotes.
  const OptionSpec* spec = find_option(option);
  return spell_options(
      spec == nullptr ? message : replace_word(message, std::string(spec->name), option_spelling(*spec, spelling)),
      spelling);
}

OptionValue parse_option_value(const OptionSpec& spec, std::string_view text) {
  text = trimmed(text);
  const bool may_be_unset = spec.default_value.index() == 0;
  if (text.empty() && may_be_unset) return std::monostate{};
  switch (spec.kind) {
    case OptionKind::Flag:
      if (text == "true" || text == "1" || text == "on") return true;
      if (text == "false" || text == "0" || text == "off") return false;
      refuse(spec, "takes true or false, got '" + std::string(text) + "'");
    case OptionKind::Integer: {
      std::int64_t n = 0;
      const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
      if (ec == std::errc() && end == text.data() + text.size() && !text.empty()) return n;
      if (ec == std::errc::result_out_of_range) refuse(spec, must(spec) + ", got " + std::string(text));
      refuse(spec, "takes a whole number, got '" + std::string(text) + "'");
    }
    case OptionKind::Real:
      if (const auto x = real_from(text)) return *x;
      refuse(spec, "takes a number, got '" + std::string(text) + "'");
    case OptionKind::Choice:
      if (!is_choice(spec, text)) refuse(spec, "must be " + choices_text(spec) + ", got '" + std::string(text) + "'");
      return std::string(text);
    case OptionKind::Choices: {
      std::vector<std::string> names;
      for (std::string_view w : words(text, ',')) names.emplace_back(w);
      return names;
    }
    case OptionKind::File:
      return std::string(text);
    case OptionKind::Box: {
      std::vector<std::string_view> parts = words(text, ' ');
      if (parts.size() == 1) parts = words(text, ',');
      std::array<double, 6> box{};
      if (parts.size() != 6) refuse(spec, "takes six numbers (xmin ymin zmin xmax ymax zmax), got '" + std::string(text) + "'");
      for (std::size_t k = 0; k < 6; ++k) {
        const auto x = real_from(parts[k]);
        if (!x) refuse(spec, "takes six numbers (xmin ymin zmin xmax ymax zmax), got '" + std::string(parts[k]) + "'");
        box[k] = *x;
      }
      return box;
    }
  }
  refuse(spec, "has an unknown kind");
}

std::string format_option_value(const OptionSpec& spec, const OptionValue& value) {
  return std::visit(
      [&](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::monostate>) {
          return "";
        } else if constexpr (std::is_same_v<T, bool>) {
          return v ? "true" : "false";
        } else if constexpr (std::is_same_v<T, std::int64_t>) {
          return std::to_string(v);
        } else if constexpr (std::is_same_v<T, double>) {
          return number_text(v);
        } else if constexpr (std::is_same_v<T, std::string>) {
          return v;
        } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
          std::string text;
          for (const std::string& name : v) text += (text.empty() ? "" : ",") + name;
          return text;
        } else {
          std::string text;
          for (double x : v) {
            if (!text.empty()) text += ' ';
            text += number_text(x);
          }
          return text;
        }
      },
      value);
  (void)spec;
}

void check_option_value(const OptionSpec& spec, const OptionValue& value) {
  if (value.index() == 0) {
    if (spec.default_value.index() != 0) refuse(spec, "must be set");
    return;
  }
  const auto wrong_kind = [&](const char* what) { refuse(spec, std::string("takes ") + what); };
  switch (spec.kind) {
    case OptionKind::Flag:
      if (!std::holds_alternative<bool>(value)) wrong_kind("true or false");
      return;
    case OptionKind::Integer: {
      if (!std::holds_alternative<std::int64_t>(value)) wrong_kind("a whole number");
      const std::int64_t n = std::get<std::int64_t>(value);
      if (!in_range(spec, static_cast<double>(n))) {
        refuse(spec, must(spec) + ", got " + std::to_string(n));
      }
      return;
    }
    case OptionKind::Real: {
      if (!std::holds_alternative<double>(value)) wrong_kind("a number");
      const double x = std::get<double>(value);
      if (std::isinf(x) && !in_range(spec, x)) refuse(spec, "must be a finite number, got " + number_text(x));
      if (!in_range(spec, x)) refuse(spec, must(spec) + ", got " + number_text(x));
      return;
    }
    case OptionKind::Choice:
      if (!std::holds_alternative<std::string>(value)) wrong_kind(("one of " + choices_text(spec)).c_str());
      if (!is_choice(spec, std::get<std::string>(value))) {
        refuse(spec, "must be " + choices_text(spec) + ", got '" + std::get<std::string>(value) + "'");
      }
      return;
    case OptionKind::Choices:
      if (!std::holds_alternative<std::vector<std::string>>(value)) wrong_kind(("some of " + choices_text(spec)).c_str());
      for (const std::string& name : std::get<std::vector<std::string>>(value)) {
        if (!is_choice(spec, name)) refuse(spec, "takes some of " + choices_text(spec) + ", got '" + name + "'");
      }
      return;
    case OptionKind::File:
      if (!std::holds_alternative<std::string>(value)) wrong_kind("a file name");
      return;
    case OptionKind::Box: {
      if (!std::holds_alternative<std::array<double, 6>>(value)) wrong_kind("six numbers");
      const auto& b = std::get<std::array<double, 6>>(value);
      for (double x : b) {
        if (!std::isfinite(x)) refuse(spec, "takes finite numbers, got " + number_text(x));
      }
      for (int k = 0; k < 3; ++k) {
        if (!(b[k] < b[k + 3])) {
          refuse(spec, "must have each minimum below its maximum, got " + format_option_value(spec, value));
        }
      }
      return;
    }
  }
}

void set_option(MeshOptions& options, const OptionSpec& spec, const OptionValue& value) {
  check_option_value(spec, value);
  spec.set(options, value);
}

void set_option(MeshOptions& options, std::string_view name, const OptionValue& value) {
  const OptionSpec* spec = find_option(name);
  if (spec == nullptr) {
    std::string known;
    for (const OptionSpec& s : kSpecs) known += (known.empty() ? "" : ", ") + std::string(s.name);
    throw Error(Error::Kind::Usage, "unknown option '" + std::string(name) + "'; the options are " + known);
  }
  set_option(options, *spec, value);
}

std::string default_text(const OptionSpec& spec) {
  if (spec.plain_default && spec.smooth_default) {
    return "default: " + number_text(*spec.plain_default) + ", or " + number_text(*spec.smooth_default) +
           " with `smooth`";
  }
  if (spec.default_value.index() == 0) return "default: " + std::string(spec.unset_means);
  if (spec.kind == OptionKind::Choices) {
    const auto& v = std::get<std::vector<std::string>>(spec.default_value);
    return v.size() == spec.choices.size() ? "default: all" : "default: " + format_option_value(spec, spec.default_value);
  }
  return "default: " + format_option_value(spec, spec.default_value);
}

std::string range_text(const OptionSpec& spec) {
  const std::string unit = spec.unit.empty() ? std::string() : concat({" ", spec.unit});
  std::string text;
  switch (spec.kind) {
    case OptionKind::Integer:
    case OptionKind::Real: {
      const bool low = std::isfinite(spec.min), high = std::isfinite(spec.max);
      if (low && high) {
        text = (spec.min_open ? "strictly between " : "between ") + number_text(spec.min) + " and " +
               number_text(spec.max) + unit;
      } else if (low) {
        text = std::string(spec.min_open ? "above " : "at least ") + number_text(spec.min) + unit;
      } else if (high) {
        text = std::string(spec.max_open ? "below " : "at most ") + number_text(spec.max) + unit;
      } else {
        text = "any number";
      }
      if (spec.also) text += ", or " + number_text(*spec.also) + " (" + std::string(spec.also_means) + ")";
      return text;
    }
    case OptionKind::Flag: return "true or false";
    case OptionKind::Choice: return "one of " + choices_text(spec);
    case OptionKind::Choices: return "any of " + choices_text(spec);
    case OptionKind::File: return "an existing file";
    case OptionKind::Box: return "six numbers, each minimum below its maximum";
  }
  return "";
}

std::vector<std::pair<std::string_view, OptionValue>> options_in_force(const MeshOptions& options) {
  std::vector<std::pair<std::string_view, OptionValue>> out;
  for (const OptionSpec& spec : kSpecs) {
    OptionValue value = spec.get(options);
    if (value.index() == 0 && spec.plain_default) {
      const double x = options.smooth ? *spec.smooth_default : *spec.plain_default;
      value = spec.kind == OptionKind::Integer ? OptionValue(static_cast<std::int64_t>(x)) : OptionValue(x);
    }
    out.emplace_back(spec.name, std::move(value));
  }
  return out;
}

void MeshOptions::check() const {
  // The values in force are checked: an unset option whose default follows `smooth` has a default
  // in range, and a set one is checked as given.
  for (const auto& [name, value] : options_in_force(*this)) check_option_value(*find_option(name), value);
  if (weld > 0 && method != Method::Clipped) {
    throw Error(Error::Kind::Usage,
                "`weld` collapses the short edges of clipped cells: it needs `method` 'clipped' (a VoroCrust mesh "
                "keeps every face planar and orthogonal to its seeds' link)",
                {.option = "weld"});
  }
  if (sliver_angle > 0 && method != Method::Clipped) {
    throw Error(Error::Kind::Usage,
                "`sliver_angle` perturbs the seeds of a clipped mesh's dual tetrahedra: it needs `method` 'clipped' "
                "(VoroCrust's seeds on the protecting spheres stay where the surface needs them)",
                {.option = "sliver_angle"});
  }
  if (!seeds_file.empty() && method != Method::Clipped) {
    throw Error(Error::Kind::Usage,
                "`seeds` gives the seeds of a clipped mesh: it needs `method` 'clipped' (VoroCrust places its own "
                "seeds about the surface; `vorocrust cells` makes the Voronoi mesh of given seeds)",
                {.option = "seeds"});
  }
}

}  // namespace vorocrust
