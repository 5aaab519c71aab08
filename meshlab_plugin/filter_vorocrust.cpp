#include "filter_vorocrust.hpp"

#include <QDir>
#include <QFileInfo>

#include <array>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>
#include <string>
#include <system_error>
#include <vector>

#include "layers_to_surface.hpp"
#include "progress_bridge.hpp"
#include "result_layers.hpp"
#include "vorocrust/vorocrust.hpp"

using vorocrust::Error;

namespace {

// Parameter names: the keys of MeshLab filter scripts (.mlx), so they stay as they are.
const char* const kLipschitz = "lipschitz";
const char* const kSharpAngle = "sharpAngle";
const char* const kSmoothSurface = "smoothSurface";
const char* const kMaxSize = "maxSize";
const char* const kSeed = "seed";
const char* const kResolveSelfIntersections = "resolveSelfIntersections";
const char* const kInterior = "interior";
const char* const kCvtIterations = "cvtIterations";
const char* const kMaxAspectRatio = "maxAspectRatio";
const char* const kOutputFolder = "outputFolder";
const char* const kWriteVtu = "writeVtu";
const char* const kWriteOpenFoam = "writeOpenFoam";
const char* const kWriteTough = "writeTough";
const char* const kWritePflotran = "writePflotran";
const char* const kWriteSeeds = "writeSeeds";
const char* const kWriteSurface = "writeSurface";
const char* const kAllVisibleLayers = "allVisibleLayers";

// How the interior of the volume is seeded (paper 2.5): the enum's entries, in
// vorocrust::InteriorMode's order.
const std::array kInteriorModes{vorocrust::InteriorMode::Random, vorocrust::InteriorMode::Lattice,
                                vorocrust::InteriorMode::Cvt};

QStringList interior_mode_names() {
  QStringList names;
  for (vorocrust::InteriorMode mode : kInteriorModes) names << vorocrust::to_string(mode);
  return names;
}

// The files the Voronoi Mesh filter writes into its output folder.
struct OutputRequest {
  std::filesystem::path folder;
  std::vector<std::string> volume;  // the volume formats (write_volume_mesh.hpp): vtu, openfoam, ...
  bool seeds = true;     // seeds.csv: the seeds, from which the whole mesh can be rebuilt
  bool surface = true;   // surface.obj and surface.ply: the conforming surface

  bool volume_wanted() const { return !volume.empty(); }
  bool any() const { return volume_wanted() || seeds || surface; }
};

struct VoronoiRequest {
  vorocrust::MeshOptions options;
  OutputRequest output;
  bool all_visible_layers = false;
};

void add_refinement_parameters(const MeshModel* m, RichParameterList& parameters) {
  const vorocrust::MeshOptions defaults;
  parameters.addParam(RichFloat(kLipschitz, float(defaults.lipschitz), "Lipschitz constant L",
                                "How fast ball radii may vary, strictly between 0 and 1: a smaller L gives more, "
                                "more evenly sized balls (VoroCrust paper, section 2.1)."));
  parameters.addParam(RichBool(kSmoothSurface, defaults.smooth, "Smooth surface",
                               "The mesh approximates a smooth surface (a scan, a coarse tessellation of a curved "
                               "shape): it is smoothed by Loop subdivision as one patch (open and non-manifold edges "
                               "stay) and its creases are found on the result, so the folds of its tessellation "
                               "are none; most surface triangles away from creases with an angle below 30 degrees are split. "
                               "Use a sharp angle of 60 with it, as the VoroCrust paper does for smooth models."));
  parameters.addParam(RichFloat(kSharpAngle, float(defaults.sharp_angle()), "Sharp angle (degrees)",
                                "An edge whose two faces' normals differ by more than this angle is a sharp crease, "
                                "kept exactly. 30 keeps the creases of CAD models; 60 suits smooth, coarsely "
                                "tessellated scans."));
  const float diagonal = m == nullptr || m->cm.bbox.IsNull() ? 0.0f : float(m->cm.bbox.Diag());
  parameters.addParam(RichAbsPerc(kMaxSize, 0.0f, 0.0f, diagonal, "Maximum size",
                                  "A uniform bound on ball radii (and cell sizes); 0 sets no bound."));
  parameters.addParam(RichInt(kSeed, 0, "Random seed",
                              "Equal input, parameters and seed give equal output, as with the vorocrust "
                              "program's --seed."));
  parameters.addParam(RichBool(kResolveSelfIntersections, true, "Resolve self-intersections",
                               "Faces that cut through each other are cut along their intersection curves, which "
                               "become creases, and each new piece of space joins a region of the input; "
                               "unchecked, such faces stop the filter with their names."));
}

// The library's options from the filter's parameters; throws Error(Usage) for a value out of range.
vorocrust::MeshOptions mesh_options(const RichParameterList& parameters, vorocrust::Stage stage) {
  vorocrust::MeshOptions options;
  options.lipschitz = parameters.getFloat(kLipschitz);
  options.smooth = parameters.getBool(kSmoothSurface);
  options.sharp_angle_degrees = parameters.getFloat(kSharpAngle);
  const float max_size = parameters.getAbsPerc(kMaxSize);
  if (max_size < 0) throw Error(Error::Kind::Usage, "the maximum size must be 0 (no bound) or positive");
  if (max_size > 0) options.max_size = max_size;
  const int seed = parameters.getInt(kSeed);
  if (seed < 0) throw Error(Error::Kind::Usage, "the random seed must be 0 or positive");
  options.seed = static_cast<std::uint64_t>(seed);
  options.self_intersections = parameters.getBool(kResolveSelfIntersections) ? vorocrust::SelfIntersections::Resolve
                                                                             : vorocrust::SelfIntersections::Refuse;
  options.stop_after = stage;
  options.check();
  return options;
}

// The run asks the library for the cells only when a volume file is wanted: the surface and the
// seeds (layers, seeds.csv, surface.*) are all there from Stage::Surface on.
VoronoiRequest voronoi_request(const RichParameterList& parameters) {
  VoronoiRequest request;
  for (const auto& [parameter, format] : {std::pair{kWriteVtu, "vtu"}, std::pair{kWriteOpenFoam, "openfoam"},
                                           std::pair{kWriteTough, "tough"}, std::pair{kWritePflotran, "pflotran"}}) {
    if (parameters.getBool(parameter)) request.output.volume.emplace_back(format);
  }
  request.output.seeds = parameters.getBool(kWriteSeeds);
  request.output.surface = parameters.getBool(kWriteSurface);
  request.options =
      mesh_options(parameters, request.output.volume_wanted() ? vorocrust::Stage::Cells : vorocrust::Stage::Surface);
  const int interior = parameters.getEnum(kInterior);
  if (interior < 0 || interior >= int(kInteriorModes.size())) {
    throw Error(Error::Kind::Usage, "unknown interior mode " + std::to_string(interior));
  }
  request.options.interior = kInteriorModes[interior];
  request.options.cvt_iterations = parameters.getInt(kCvtIterations);
  request.options.max_aspect_ratio = parameters.getFloat(kMaxAspectRatio);
  request.options.check();
  const QString folder = parameters.getString(kOutputFolder).trimmed();
  if (request.output.any() && folder.isEmpty()) throw Error(Error::Kind::Usage, "no output folder given");
  request.output.folder = folder.toStdString();
  request.all_visible_layers = parameters.getBool(kAllVisibleLayers);
  return request;
}

// Makes the output folder before the run, so that a folder that cannot be made stops the filter
// before the meshing rather than after it.
void make_output_folder(const OutputRequest& output) {
  if (!output.any()) return;
  std::error_code ec;
  std::filesystem::create_directories(output.folder, ec);
  if (ec || !std::filesystem::is_directory(output.folder)) {
    throw Error(Error::Kind::Output, "cannot make the output folder: " + (ec ? ec.message() : "not a folder"),
                {.file = output.folder.string()});
  }
}

// Writes the files asked for, each atomically, and returns their names. Files of earlier runs
// that were not asked for this time are left as they are.
QStringList write_outputs(const vorocrust::MeshResult& result, const OutputRequest& output) {
  QStringList written;
  const auto write = [&](bool wanted, const char* name, const auto& writer) {
    if (!wanted) return;
    writer(output.folder / name);
    written << name;
  };
  const vorocrust::CellQuality* quality = result.cell_quality ? &*result.cell_quality : nullptr;
  for (const vorocrust::VolumeFormat& f : vorocrust::volume_formats()) {
    const bool wanted = std::find(output.volume.begin(), output.volume.end(), f.name) != output.volume.end();
    write(wanted, f.output, [&](const auto&) { vorocrust::write_volume_format(result.cells, output.folder, f.name, quality); });
  }
  write(output.seeds, "seeds.csv", [&](const auto& path) { vorocrust::write_seeds_csv(result.seeds, path); });
  write(output.surface, "surface.obj", [&](const auto& path) { vorocrust::write_mesh(result.surface, path); });
  write(output.surface, "surface.ply", [&](const auto& path) { vorocrust::write_mesh(result.surface, path); });
  return written;
}

// The default output folder: "NAME_vorocrust" beside the layer's file, or in the home folder.
QString default_output_folder(const MeshModel* m) {
  if (m == nullptr || m->fullName().isEmpty()) return QDir::home().filePath("mesh_vorocrust");
  const QFileInfo file(m->fullName());
  return file.absoluteDir().filePath(file.completeBaseName() + "_vorocrust");
}

// Validates the surface as the vorocrust program does before meshing: orientation problems are
// fixed in the copy (the layers stay as they are), warnings are logged, and error findings
// (zero-area or duplicate faces, self-intersections unless they are resolved) stop the filter
// with their messages.
template <class Logger>
void check_input(vorocrust::SurfaceMesh& surface, const vorocrust::MeshOptions& options, Logger&& log) {
  const vorocrust::ValidationReport report = vorocrust::validate(
      surface, {.self_intersections_are_errors = options.self_intersections == vorocrust::SelfIntersections::Refuse});
  std::string errors;
  for (const vorocrust::Finding& f : report.findings) {
    if (f.severity == vorocrust::Finding::Severity::Error) {
      errors += "\n" + f.message;
    } else if (f.severity != vorocrust::Finding::Severity::Note) {
      log(std::string(to_string(f.severity)) + ": " + f.message);
    }
  }
  if (!errors.empty()) {
    throw Error(Error::Kind::InvalidGeometry, "the input surface cannot be meshed:" + errors);
  }
}

std::string describe_surface(const vorocrust::MeshResult& result) {
  std::string text = std::to_string(result.seeds.size()) + " seeds; a surface of " +
                     std::to_string(result.surface.num_faces()) + " triangles";
  if (const auto& q = result.surface_quality) {
    char figures[200];
    std::snprintf(figures, sizeof figures,
                  ", smallest angle %.1f deg, Q min %.3f mean %.3f, Hausdorff %.3f %% of the diagonal, topology %s",
                  q->min_angle_degrees, q->min_quality, q->mean_quality, 100 * q->hausdorff_relative,
                  q->topology_matches ? "as the input's" : "DIFFERS from the input's");
    text += figures;
  }
  if (!result.cells.cells.empty()) text += "; " + std::to_string(result.cells.cells.size()) + " cells";
  return text;
}

std::string describe(const vorocrust::MeshResult& result) {
  const vorocrust::RefinementStats& r = result.refinement;
  const vorocrust::SelfIntersectionStats& s = result.self_intersections;
  const std::string resolved =
      s.faces_cut == 0 ? "" : "self-intersections resolved (" + std::to_string(s.faces_cut) + " faces cut, " +
                                  std::to_string(s.faces_dropped) + " inside one region dropped); ";
  return resolved + std::to_string(result.balls.size()) + " balls (" + std::to_string(r.balls[0]) + " corner, " +
         std::to_string(r.balls[1]) + " crease, " + std::to_string(r.balls[2]) + " patch); " +
         std::to_string(result.features.corners) + " corners, " + std::to_string(result.features.creases) +
         " creases, " + std::to_string(result.features.patches) + " patches";
}

}  // namespace

FilterVoroCrustPlugin::FilterVoroCrustPlugin() {
  typeList << FP_PROTECTING_BALLS << FP_VORONOI_MESH;
  for (FilterIDType id : types()) actionList << new QAction(filterName(id), this);
}

QString FilterVoroCrustPlugin::pluginName() const { return "FilterVoroCrust"; }

QString FilterVoroCrustPlugin::filterName(FilterIDType filter) const {
  switch (filter) {
    case FP_PROTECTING_BALLS: return "VoroCrust Protecting Balls";
    case FP_VORONOI_MESH: return "VoroCrust Voronoi Mesh";
  }
  return {};
}

QString FilterVoroCrustPlugin::filterInfo(FilterIDType filter) const {
  const QString paper =
      "<br><br>See: <i>A. Abdelkader, C. L. Bajaj, M. S. Ebeida, A. H. Mahmoud, S. A. Mitchell, J. D. Owens, "
      "A. A. Rushdi</i>, <b>\"VoroCrust: Voronoi Meshing Without Clipping\"</b>, ACM Transactions on Graphics.";
  switch (filter) {
    case FP_PROTECTING_BALLS:
      return "Covers the current mesh with the protecting balls of VoroCrust's refinement (paper section 2.3): "
             "balls centred on the surface, on its sharp corners, creases and smooth patches. Adds a point "
             "layer with one vertex per ball centre: the radius is the per-vertex attribute <i>radius</i> and "
             "the vertex quality, the stratum is in <i>stratum_type</i> (0 corner, 1 crease, 2 patch) and "
             "<i>stratum_index</i>, and the colour shows the stratum type. The mesh is validated first: "
             "zero-area or duplicate faces stop the filter, and so do faces cutting through each other "
             "unless they are resolved (cut along their intersection curves)." +
             paper;
    case FP_VORONOI_MESH:
      return "Meshes the volume the current mesh bounds (or the volumes of all visible layers, each a "
             "material) into conforming Voronoi cells with VoroCrust: true Voronoi cells, convex, that "
             "conform to the surface without clipping. Writes the volume mesh into the output folder "
             "(mesh.vtu for ParaView, an OpenFOAM case, TOUGH's MESH, a PFLOTRAN grid, seeds.csv, the "
             "conforming surface) and adds layers "
             "for the conforming surface (faces coloured by the region pair they separate, which the face "
             "attributes <i>back_region</i> and <i>front_region</i> hold, and the triangle quality as face "
             "quality for MeshLab's histogram) and the seeds (label, kind and radius as vertex attributes, "
             "the radius also as vertex quality, coloured by label).<br><br>The cells are computed only when "
             "a volume format is asked for: the surface and the seeds alone take the library "
             "as far as its surface stage." +
             paper;
  }
  return {};
}

MeshFilterInterface::FilterClass FilterVoroCrustPlugin::getClass(QAction*) { return Remeshing; }

MeshFilterInterface::FILTER_ARITY FilterVoroCrustPlugin::filterArity(QAction* action) const {
  return ID(action) == FP_VORONOI_MESH ? VARIABLE : SINGLE_MESH;
}

int FilterVoroCrustPlugin::getPreConditions(QAction*) const { return MeshModel::MM_FACENUMBER; }

// Both filters add layers and leave the input layers as they are.
int FilterVoroCrustPlugin::postCondition(QAction*) const { return MeshModel::MM_NONE; }

void FilterVoroCrustPlugin::initParameterSet(QAction* action, MeshDocument& md, RichParameterList& parameters) {
  const MeshModel* m = md.mm();
  add_refinement_parameters(m, parameters);
  if (ID(action) != FP_VORONOI_MESH) return;
  parameters.addParam(RichEnum(kInterior, 0, interior_mode_names(), "Interior seeds",
                               "random: dart throwing with the Lipschitz sizing; lattice: a cubic lattice of the "
                               "local size, giving hex-dominant cells; cvt: random, then Lloyd iterations towards "
                               "centroidal cells (paper section 2.5)."));
  parameters.addParam(RichInt(kCvtIterations, vorocrust::MeshOptions().cvt_iterations, "CVT iterations",
                              "Lloyd iterations of the cvt interior mode."));
  parameters.addParam(RichFloat(kMaxAspectRatio, float(vorocrust::MeshOptions().max_aspect_ratio),
                                "Largest cell aspect ratio",
                                "Cells whose aspect ratio (enclosing sphere over inscribed ball) exceeds this get a "
                                "seed at their centroid, for at most two rounds; 0 splits none, else at least 3."));
  parameters.addParam(RichString(kOutputFolder, default_output_folder(m), "Output folder",
                                 "Where the files asked for are written (made when missing); files not asked for "
                                 "are left as they are."));
  parameters.addParam(RichBool(kWriteVtu, true, "Write mesh.vtu",
                               "A VTK unstructured grid of polyhedral cells. Needs the cells: with neither this nor "
                               "the OpenFOAM case, the run stops after the surface."));
  parameters.addParam(RichBool(kWriteOpenFoam, true, "Write an OpenFOAM case",
                               "case/ with constant/polyMesh, ready for checkMesh: a cell zone per material, a "
                               "patch per boundary region pair, a face zone per interface. Needs the cells."));
  parameters.addParam(RichBool(kWriteTough, true, "Write a TOUGH MESH file",
                               "MESH with the ELEME and CONNE blocks TOUGH2 and TOUGH3 read. Needs the cells."));
  parameters.addParam(RichBool(kWritePflotran, true, "Write a PFLOTRAN grid",
                               "pflotran/ with mesh.uge (explicit unstructured grid), a cell list per material "
                               "and boundary connections per patch. Needs the cells."));
  parameters.addParam(
      RichBool(kWriteSeeds, true, "Write seeds.csv", "The seeds with label and radius: they define the whole mesh."));
  parameters.addParam(
      RichBool(kWriteSurface, true, "Write the surface", "surface.obj and surface.ply, the conforming surface."));
  parameters.addParam(RichBool(kAllVisibleLayers, false, "All visible layers as materials",
                               "Mesh the surfaces of all visible layers together, each layer a material; "
                               "otherwise the current layer alone."));
}

bool FilterVoroCrustPlugin::applyFilter(QAction* action, MeshDocument& md, const RichParameterList& parameters,
                                        vcg::CallBackPos* cb) {
  errorMessage.clear();
  try {
    if (md.mm() == nullptr) throw Error(Error::Kind::Usage, "there is no current layer");
    switch (ID(action)) {
      case FP_PROTECTING_BALLS: protecting_balls(md, parameters, cb); return true;
      case FP_VORONOI_MESH: voronoi_mesh(md, parameters, cb); return true;
    }
    return fail("VoroCrust: unknown filter");
  } catch (const Error& e) {
    return fail(QString("VoroCrust: %1: %2").arg(to_string(e.kind()), QString::fromStdString(e.what())));
  } catch (const std::bad_alloc&) {
    return fail("VoroCrust: out of memory");
  } catch (const std::exception& e) {
    return fail(QString("VoroCrust: internal error: %1").arg(QString::fromStdString(e.what())));
  } catch (...) {
    return fail("VoroCrust: internal error: an unknown exception");
  }
}

bool FilterVoroCrustPlugin::fail(const QString& message) {
  errorMessage = message.toHtmlEscaped().replace("\n", "<br>");
  // meshlabserver prints the log, not errorMessage: say it there too.
  Log(GLLogStream::WARNING, qUtf8Printable(message));
  return false;
}

void FilterVoroCrustPlugin::protecting_balls(MeshDocument& md, const RichParameterList& parameters,
                                             vcg::CallBackPos* cb) {
  const vorocrust::MeshOptions options = mesh_options(parameters, vorocrust::Stage::Balls);
  MeshModel& source = *md.mm();
  vorocrust::SurfaceMesh surface = vorocrust::meshlab::surface_from_layers({&source});
  check_input(surface, options, [this](const std::string& line) { Log("VoroCrust: %s", line.c_str()); });
  const vorocrust::MeshResult result =
      vorocrust::generate_mesh(surface, options, vorocrust::meshlab::progress_to(cb));
  MeshModel* layer = vorocrust::meshlab::add_balls_layer(md, result.balls, source);
  Log("VoroCrust: %s, in layer \"%s\"", describe(result).c_str(), qUtf8Printable(layer->label()));
}

void FilterVoroCrustPlugin::voronoi_mesh(MeshDocument& md, const RichParameterList& parameters, vcg::CallBackPos* cb) {
  const VoronoiRequest request = voronoi_request(parameters);
  MeshModel& current = *md.mm();
  std::vector<const MeshModel*> layers;
  if (request.all_visible_layers) {
    for (const MeshModel* layer : md.meshList) {
      if (!layer->visible) continue;
      if (layer->cm.fn == 0) {
        Log("VoroCrust: layer \"%s\" has no faces and is left out", qUtf8Printable(layer->label()));
        continue;
      }
      layers.push_back(layer);
    }
    if (layers.empty()) throw Error(Error::Kind::InvalidGeometry, "no visible layer has faces");
  } else {
    layers.push_back(&current);
  }
  const vorocrust::MeshOptions& options = request.options;
  if (options.stop_after == vorocrust::Stage::Cells) {
    Log("VoroCrust: %zu layer(s), up to the cells, interior seeds: %s", layers.size(), to_string(options.interior));
  } else {
    Log("VoroCrust: %zu layer(s), up to the surface (no volume file asked for)", layers.size());
  }

  vorocrust::SurfaceMesh surface = vorocrust::meshlab::surface_from_layers(layers);
  check_input(surface, options, [this](const std::string& line) { Log("VoroCrust: %s", line.c_str()); });
  make_output_folder(request.output);
  const vorocrust::MeshResult result =
      vorocrust::generate_mesh(surface, options, vorocrust::meshlab::progress_to(cb));
  const QStringList written = write_outputs(result, request.output);
  const vorocrust::meshlab::ResultLayers added =
      vorocrust::meshlab::add_result_layers(md, result, options.stop_after, current);
  Log("VoroCrust: %s; %s", describe(result).c_str(), describe_surface(result).c_str());
  Log("VoroCrust: layers \"%s\" and \"%s\"", qUtf8Printable(added.surface->label()),
      qUtf8Printable(added.seeds->label()));
  if (!written.isEmpty()) {
    Log("VoroCrust: wrote %s in %s", qUtf8Printable(written.join(", ")), request.output.folder.string().c_str());
  }
}
