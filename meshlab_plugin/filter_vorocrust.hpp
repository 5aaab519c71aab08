// filter_vorocrust — the VoroCrust filters for MeshLab 2020.09.
//
// A thin adapter: its parameters are the library's option table (option_parameters.hpp); it turns
// MeshLab layers into a vorocrust::SurfaceMesh (layers_to_surface.hpp), runs the library's job
// (vorocrust::run_job: validation, meshing, the files asked for, report.json) and turns the
// result back into layers (result_layers.hpp). It holds no meshing code of its own.
//
// Both filters sit in "Filters > Remeshing, Simplification and Reconstruction":
//   "VoroCrust Protecting Balls"  the refinement only: a point layer of ball centres with radius;
//   "VoroCrust Voronoi Mesh"      the pipeline to the surface, or to the cells when volume files are
//                                 asked for: surface and seeds layers, the files in a folder.
//
// applyFilter never lets an exception out (MeshLab runs filters in its own process, and an
// escaping exception would end the user's session): every failure becomes errorMessage, is
// logged, and the filter returns false.
#pragma once

#include <common/interfaces.h>

#include "vorocrust/job.hpp"

class FilterVoroCrustPlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

 public:
  enum { FP_PROTECTING_BALLS, FP_VORONOI_MESH };

  FilterVoroCrustPlugin();

  QString pluginName() const override;
  QString filterName(FilterIDType filter) const override;
  QString filterInfo(FilterIDType filter) const override;
  FilterClass getClass(QAction* action) override;
  FILTER_ARITY filterArity(QAction* action) const override;
  int getPreConditions(QAction* action) const override;
  int postCondition(QAction* action) const override;
  using MeshFilterInterface::initParameterSet;
  // The document's overload, which (unlike the base class) copes with a document without layers.
  void initParameterSet(QAction* action, MeshDocument& md, RichParameterList& parameters) override;
  bool applyFilter(QAction* action, MeshDocument& md, const RichParameterList& parameters,
                   vcg::CallBackPos* cb) override;

 private:
  // Runs the job, logging its warnings and summary.
  vorocrust::JobResult run(const vorocrust::Job& job, vcg::CallBackPos* cb);
  void protecting_balls(MeshDocument& md, const RichParameterList& parameters, vcg::CallBackPos* cb);
  void voronoi_mesh(MeshDocument& md, const RichParameterList& parameters, vcg::CallBackPos* cb);
  // Sets errorMessage (as HTML: MeshLab's window shows it as rich text), logs it, returns false.
  bool fail(const QString& message);
};
