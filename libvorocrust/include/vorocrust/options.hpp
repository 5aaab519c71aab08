// vorocrust/options.hpp — every option of a mesh run, declared once.
//
// MeshOptions holds a run's options as the pipeline reads them. mesh_option_specs() declares each
// of them once, as geogram declares its command-line arguments: name, kind, default, range or
// choices, help, the paper's section, the front ends that offer it, and how `smooth` (the preset
// for scans and coarse tessellations of smooth shapes) changes its default. The front ends are
// made from this table and hold no option of their own: the CLI's flags and --help, the Python
// keyword arguments and docstring, the MeshLab filter's parameters, the FreeCAD task panel and
// object properties. Adding an option is one entry in the table (options.cpp), its field here,
// and its use in the pipeline.
//
// Contract:
// - Names are snake_case and each front end spells them its own way, by one rule
//   (option_spelling): `--sharp-angle`, sharp_angle=, sharpAngle, SharpAngle.
// - An option may be unset (OptionValue holds std::monostate): its default then depends on other
//   options (sharp_angle is 30, or 60 with smooth) or means "none" (max_size: no bound). Front
//   ends whose widgets hold a number show unset as OptionSpec::unset_number.
// - check_option_value and MeshOptions::check throw Error(Usage) whose message names the option
//   by its table name (and whose where().option holds it), never by one front end's spelling.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "vorocrust/api.hpp"
#include "vorocrust/modes.hpp"
#include "vorocrust/outputs.hpp"

namespace vorocrust {

struct VOROCRUST_API MeshOptions {
  Method method = Method::Vorocrust;  // the paper's cells, or Voronoi cells clipped to the input
  double lipschitz = 0.25;  // L < 1: how fast ball radii may vary (2.1)
  // The input approximates a smooth surface (a scan, a coarse tessellation of a curved shape): it
  // is smoothed as one patch (only boundary and non-manifold edges stay fixed), and its features
  // are found afterwards, on the smoothed surface, so the folds of its tessellation are not
  // creases. A preset: it changes the defaults of sharp_angle, smoothing_iterations and
  // min_triangle_angle to the paper's settings for smooth models.
  bool smooth = false;
  // theta#: an edge whose faces' normals differ by more than this is a sharp crease; it also
  // bounds how far normals may turn between co-smooth points. Unset: 30 degrees, which keeps
  // every crease of the shared CAD models while the tessellation rings of curved surfaces (22.5
  // degrees on sandia_torus) stay smooth; 60 with `smooth`.
  std::optional<double> sharp_angle_degrees;
  double max_size = std::numeric_limits<double>::infinity();  // uniform sizing bound
  std::filesystem::path sizing_file;  // optional: lines "x y z size", interpolated
  // Rounds of adaptive Loop subdivision inside patches (paper 2.2 uses 6), at most: fewer are
  // applied when more would make a feature. Unset: 0, as on CAD models it costs more than it
  // gives; 6 with `smooth`.
  std::optional<int> smoothing_iterations;
  // How far smoothing should move the surface from the input at most, as a fraction of the
  // input's bounding-box diagonal (a target): the faces around a vertex that Loop's rules would
  // move farther are split at their edge midpoints first, up to twice (features/smooth_patches.hpp).
  double smoothing_tolerance = kDefaultSmoothingTolerance;
  // Surface triangles of patch balls with an angle below this are split by shrinking the balls
  // that cover their circumcentres deeply (seeds/skinny_triangles.hpp). Unset: 0 (none), 30 with
  // `smooth`. At most 30: deep coverage bounds angles by 30 degrees only.
  std::optional<double> min_triangle_angle_degrees;
  // The domain around open sheets (paper Figure 17): {xmin, ymin, zmin, xmax, ymax, zmax}. Its
  // sides join the surface and what is outside every material inside it becomes the material
  // "domain". Unset: an input with open edges gets its bounding box grown by a tenth of its
  // diagonal on every side; a closed input gets none.
  std::optional<std::array<double, 6>> box;
  SelfIntersections self_intersections = SelfIntersections::Resolve;
  InteriorMode interior = InteriorMode::Random;
  int cvt_iterations = 20;  // Lloyd iterations of InteriorMode::Cvt
  // With Method::Clipped: edges shorter than this fraction of the seeds' radius collapse to one
  // point (Ebeida and Mitchell's welding; 1e-4 is theirs), leaving faces slightly non-planar
  // (cells/weld_short_edges.hpp). 0 welds none.
  double weld = 0;
  // With Method::Clipped: the seeds of dual tetrahedra with a dihedral angle below this many
  // degrees move at random, each move kept where it improves them (Yan et al.'s sliver
  // perturbation; clipping/clipped_cells.hpp). 0 moves none.
  double sliver_angle = 0;
  // With Method::Clipped: the seeds (OUTDIR/seeds.csv's form) instead of sampled ones; each seed
  // of a material must lie in its region, outside seeds are ignored. `interior` Cvt moves them.
  std::filesystem::path seeds_file;
  // Cells whose aspect ratio (smallest enclosing sphere over largest inscribed ball) exceeds this
  // get a seed at their centroid, for at most 2 rounds (cells/repair_cells.hpp); 0 splits none.
  // 5 by default, above the paper's 4.86 for its smooth model.
  double max_aspect_ratio = kDefaultMaxAspectRatio;
  // Faces between two cells more skew than this (checkMesh's skewness) get a repair seed
  // (cells/repair_seeds.hpp). 4 by default, where checkMesh calls a face highly skew.
  double max_skewness = kDefaultMaxSkewness;
  Stage stop_after = Stage::Cells;
  std::uint64_t seed = 0;  // random seed; equal seeds give equal meshes
  int threads = 0;         // worker threads, 0 = all hardware threads; results do not depend on it
  // A run whose estimated peak memory (vorocrust/memory.hpp) exceeds this many gigabytes is
  // refused once its seeds are placed, before the cells: no bound by default.
  double max_memory_gb = std::numeric_limits<double>::infinity();
  // What run_job writes into its output folder (generate_mesh ignores it): every format by
  // default.
  std::vector<OutputFormat> formats = all_output_formats();

  static constexpr double kDefaultSmoothingTolerance = 0.0075;
  static constexpr double kDefaultMaxAspectRatio = 5, kLowestMaxAspectRatio = 3;
  static constexpr double kDefaultMaxSkewness = 4;
  static constexpr double kSharpAngleDegrees = 30, kSmoothSharpAngleDegrees = 60;
  static constexpr int kSmoothSmoothingIterations = 6;
  static constexpr double kSmoothMinTriangleAngleDegrees = 30, kMaxMinTriangleAngleDegrees = 30;
  static constexpr std::uint64_t kMaxSeed = std::numeric_limits<std::int32_t>::max();

  // The values in force: the ones set, or the defaults of the mode.
  double sharp_angle() const {
    return sharp_angle_degrees.value_or(smooth ? kSmoothSharpAngleDegrees : kSharpAngleDegrees);
  }
  int smoothing_rounds() const { return smoothing_iterations.value_or(smooth ? kSmoothSmoothingIterations : 0); }
  double min_triangle_angle() const {
    return min_triangle_angle_degrees.value_or(smooth ? kSmoothMinTriangleAngleDegrees : 0);
  }
  bool writes(OutputFormat format) const;

  // Throws Error(Usage) naming the first option out of its range (by its table name).
  void check() const;

  static std::vector<OutputFormat> all_output_formats();
};

// What kind of value an option takes.
enum class OptionKind {
  Flag,     // on or off
  Integer,  // a whole number in [min, max]
  Real,     // a number in its range
  Choice,   // one of `choices`
  Choices,  // some of `choices` (a list)
  File,     // a path to an existing file
  Box,      // six numbers: xmin ymin zmin xmax ymax zmax
};

// A value of some option: unset (std::monostate), or of its kind's type. Integers are held as
// int64 (seed included: its range keeps it below 2^31).
using OptionValue =
    std::variant<std::monostate, bool, std::int64_t, double, std::string, std::vector<std::string>, std::array<double, 6>>;

// Which front ends offer an option.
enum FrontEnd : unsigned { kCli = 1, kPython = 2, kMeshLab = 4, kFreeCad = 8, kEveryFrontEnd = 15 };

struct VOROCRUST_API OptionSpec {
  std::string_view name;     // snake_case: the Python keyword, report.json's key
  OptionKind kind;
  std::string_view label;    // what a dialog calls it: "Lipschitz constant L"
  std::string_view help;     // what it does, one paragraph, in no front end's spelling
  std::string_view section;  // the paper's section: "2.1"; empty where the paper says nothing
  std::string_view unit;     // "degrees", or empty
  std::string_view group;    // a dialog's group: "Surface", "Interior", "Run", "Outputs"
  OptionValue default_value;  // std::monostate: unset by default (see unset_means)
  // Integer and Real: the range, each end open or closed; `also` is one more value allowed
  // outside it (max_aspect_ratio's 0: no splits), with what it means.
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false, max_open = false;
  std::optional<double> also;
  std::string_view also_means;
  std::span<const std::string_view> choices;  // Choice and Choices
  // What an unset value means ("no bound"); for an option whose default follows `smooth`, the
  // two defaults instead.
  std::string_view unset_means;
  std::optional<double> plain_default, smooth_default;
  std::optional<double> unset_number;  // how a numeric widget shows unset (0 or -1), if it may be
  unsigned front_ends = kEveryFrontEnd;
  std::string_view cli_alias;  // one more command-line spelling, kept for scripts ("--format")
  OptionValue (*get)(const MeshOptions&) = nullptr;
  void (*set)(MeshOptions&, const OptionValue&) = nullptr;
};

// Every option, in the order front ends list them.
VOROCRUST_API std::span<const OptionSpec> mesh_option_specs() noexcept;
// The option named `name`, or nullptr.
VOROCRUST_API const OptionSpec* find_option(std::string_view name) noexcept;

// How each front end spells an option's name: sharp_angle, --sharp-angle, sharpAngle (a MeshLab
// filter script's key), SharpAngle (a FreeCAD property), or "Sharp angle" (a dialog's label, in
// quotes).
enum class Spelling { Python, Cli, MeshLab, FreeCad, Label };
VOROCRUST_API std::string option_spelling(const OptionSpec& spec, Spelling spelling);
// `text` with every option name in it (a whole word) spelled as `spelling` spells it: for help
// texts, which name other options.
VOROCRUST_API std::string spell_options(const std::string& text, Spelling spelling);
// `message` with the option `option` (an Error's where().option) spelled as `spelling` spells it,
// and any other option named in backquotes.
VOROCRUST_API std::string spelled_message(const std::string& message, const std::string& option, Spelling spelling);

// The value `text` gives the option, as a command line or a dialog's text field gives it: "true",
// "0.3", "cvt", "vtu,openfoam" (Choices), "0 0 0 1 1 1" (Box), "" (unset, where the option may be
// unset). Throws Error(Usage) naming the option when the text is no such value.
VOROCRUST_API OptionValue parse_option_value(const OptionSpec& spec, std::string_view text);
// The value as text parse_option_value reads back; "" for unset.
VOROCRUST_API std::string format_option_value(const OptionSpec& spec, const OptionValue& value);
// Throws Error(Usage) naming the option when `value` is not of its kind or out of its range.
VOROCRUST_API void check_option_value(const OptionSpec& spec, const OptionValue& value);
// Checks the value and sets it in `options`.
VOROCRUST_API void set_option(MeshOptions& options, const OptionSpec& spec, const OptionValue& value);
// By name; throws Error(Usage) naming an unknown option and listing the known ones.
VOROCRUST_API void set_option(MeshOptions& options, std::string_view name, const OptionValue& value);

// One sentence on the default ("default: 30, or 60 with smooth") and one on the range ("range:
// 0 < x < 90 degrees"), as every front end appends them to the option's help.
VOROCRUST_API std::string default_text(const OptionSpec& spec);
VOROCRUST_API std::string range_text(const OptionSpec& spec);

// Every option of `options` that the table declares, by name, with the values in force (an unset
// option whose default follows `smooth` resolved): what report.json records under "options".
VOROCRUST_API std::vector<std::pair<std::string_view, OptionValue>> options_in_force(const MeshOptions& options);

inline bool MeshOptions::writes(OutputFormat format) const {
  for (OutputFormat f : formats) {
    if (f == format) return true;
  }
  return false;
}

}  // namespace vorocrust
