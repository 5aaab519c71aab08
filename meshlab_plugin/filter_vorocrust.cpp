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
#include "option_parameters.hpp"
#include "progress_bridge.hpp"
#include "result_layers.hpp"
#include "vorocrust/vorocrust.hpp"

using vorocrust::Error;

namespace {

// The filters' own parameters; the options of the run come from the library's table
// (option_parameters.hpp).
const char* const kOutputFolder = "outputFolder";
const char* const kAllVisibleLayers = "allVisibleLayers";

// What the Protecting Balls filter offers: the options the balls depend on.
const std::vector<std::string_view> kBallOptions = {"lipschitz",          "smooth",
                                                    "sharp_angle",        "max_size",
                                                    "sizing",             "smoothing_iterations",
                                                    "smoothing_tolerance", "box",
                                                    "self_intersections", "seed",
                                                    "threads"};

// The default output folder: "NAME_vorocrust" beside the layer's file, or in the home folder.
QString default_output_folder(const MeshModel* m) {
  if (m == nullptr || m->fullName().isEmpty()) return QDir::home().filePath("mesh_vorocrust");
  const QFileInfo file(m->fullName());
  return file.absoluteDir().filePath(file.completeBaseName() + "_vorocrust");
}

bool wants_cells(const vorocrust::MeshOptions& options) {
  return std::any_of(options.formats.begin(), options.formats.end(),
                     [](vorocrust::OutputFormat f) { return vorocrust::output_format(f).volume; });
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
  if (ID(action) == FP_PROTECTING_BALLS) {
    vorocrust::meshlab::add_option_parameters(parameters, kBallOptions);
    return;
  }
  vorocrust::meshlab::add_option_parameters(parameters);
  parameters.addParam(RichString(kOutputFolder, default_output_folder(md.mm()), "Output folder",
                                 "Where the outputs asked for and report.json are written (made when missing). "
                                 "Outputs of an earlier run there that this run does not write are removed, so "
                                 "that none passes for this run's."));
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
    const std::string message = vorocrust::spelled_message(e.what(), e.where().option, vorocrust::Spelling::Label);
    return fail(QString("VoroCrust: %1: %2").arg(to_string(e.kind()), QString::fromStdString(message)));
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

vorocrust::JobResult FilterVoroCrustPlugin::run(const vorocrust::Job& job, vcg::CallBackPos* cb) {
  vorocrust::JobResult result = vorocrust::run_job(job, vorocrust::meshlab::progress_to(cb), [this](const std::string& line) {
    Log("VoroCrust: %s", vorocrust::spell_options(line, vorocrust::Spelling::Label).c_str());
  });
  for (const std::string& line : result.summary) Log("VoroCrust: %s", line.c_str());
  return result;
}

void FilterVoroCrustPlugin::protecting_balls(MeshDocument& md, const RichParameterList& parameters,
                                             vcg::CallBackPos* cb) {
  vorocrust::Job job;
  job.options = vorocrust::meshlab::options_from_parameters(parameters);
  job.options.stop_after = vorocrust::Stage::Balls;
  MeshModel& source = *md.mm();
  job.model = vorocrust::meshlab::surface_from_layers({&source});
  const vorocrust::JobResult result = run(job, cb);
  MeshModel* layer = vorocrust::meshlab::add_balls_layer(md, result.mesh.balls, source);
  Log("VoroCrust: layer \"%s\"", qUtf8Printable(layer->label()));
}

void FilterVoroCrustPlugin::voronoi_mesh(MeshDocument& md, const RichParameterList& parameters, vcg::CallBackPos* cb) {
  vorocrust::Job job;
  job.options = vorocrust::meshlab::options_from_parameters(parameters);
  // The layers need the surface at least; the cells are made only when a volume file is asked for.
  if (!wants_cells(job.options)) job.options.stop_after = std::min(job.options.stop_after, vorocrust::Stage::Surface);
  const QString folder = parameters.getString(kOutputFolder).trimmed();
  if (!job.options.formats.empty() && folder.isEmpty()) {
    throw Error(Error::Kind::Usage, "no output folder given for the outputs asked for");
  }
  job.output_dir = folder.toStdString();
  MeshModel& current = *md.mm();
  std::vector<const MeshModel*> layers;
  if (parameters.getBool(kAllVisibleLayers)) {
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
  Log("VoroCrust: %zu layer(s), up to the %s%s", layers.size(), to_string(job.options.stop_after),
      wants_cells(job.options) ? "" : " (no volume file asked for)");
  job.model = vorocrust::meshlab::surface_from_layers(layers);
  for (const MeshModel* layer : layers) job.inputs.push_back(layer->fullName().isEmpty() ? layer->label().toStdString()
                                                                                          : layer->fullName().toStdString());
  const vorocrust::JobResult result = run(job, cb);
  const vorocrust::meshlab::ResultLayers added =
      vorocrust::meshlab::add_result_layers(md, result.mesh, job.options.stop_after, current);
  if (added.balls) {
    Log("VoroCrust: layer \"%s\"", qUtf8Printable(added.balls->label()));
  } else {
    Log("VoroCrust: layers \"%s\" and \"%s\"", qUtf8Printable(added.surface->label()),
        qUtf8Printable(added.seeds->label()));
  }
  if (!job.output_dir.empty()) Log("VoroCrust: wrote %zu outputs in %s", result.written.size(), job.output_dir.c_str());
}
