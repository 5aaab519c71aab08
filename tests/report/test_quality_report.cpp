// The surface- and cell-quality JSON, the cells run's report.json, and reading a run's inputs back
// from its report.json.
#include <gtest/gtest.h>

#include <limits>
#include <nlohmann/json.hpp>

#include "cells/seed_sets.hpp"
#include "test_support.hpp"
#include "vorocrust/atomic_file.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/read_mesh.hpp"
#include "vorocrust/report.hpp"

namespace vorocrust {
namespace {

TEST(QualityReport, JsonHoldsThePaperFiguresWithTheirUnits) {
  const SurfaceMesh bunny = read_mesh(test::model("igl_bunny.off"));
  const SurfaceMesh torus = read_mesh(test::model("sandia_torus.obj"));
  const SurfaceQuality q = measure_surface_quality(bunny, torus);
  const nlohmann::json doc = nlohmann::json::parse(surface_quality_json(q));
  EXPECT_EQ(doc["triangles"], 9216);
  EXPECT_EQ(doc["angles"]["min_degrees"].get<double>(), q.min_angle_degrees);
  EXPECT_EQ(doc["angles"]["percent_below_30_degrees"].get<double>(), q.percent_angles_below_30);
  EXPECT_EQ(doc["angles"]["percent_above_90_degrees"].get<double>(), q.percent_angles_above_90);
  EXPECT_EQ(doc["triangle_quality"]["min"].get<double>(), q.min_quality);
  EXPECT_EQ(doc["triangle_quality"]["histogram"]["counts"].get<std::vector<std::size_t>>(), q.quality_histogram);
  EXPECT_DOUBLE_EQ(doc["hausdorff"]["percent_of_bounding_box_diagonal"].get<double>(), 100 * q.hausdorff_relative);
  EXPECT_EQ(doc["hausdorff"]["input_to_output"].get<double>(), q.input_to_output);
  EXPECT_EQ(doc["hausdorff"]["output_to_input"].get<double>(), q.output_to_input);
  EXPECT_FALSE(doc["topology"]["matches"].get<bool>());
  EXPECT_EQ(doc["topology"]["input"]["euler_characteristic"], nlohmann::json::array({2}));
  EXPECT_EQ(doc["topology"]["output"]["euler_characteristic"], nlohmann::json::array({0}));
  EXPECT_EQ(doc["topology"]["output"]["closed"], nlohmann::json::array({true}));
}

TEST(QualityReport, CellJsonHoldsTheVolumeFigures) {
  const auto seeds = test::lattice_seeds(7, 0.3, test::ball_region(Point(3, 3, 3), 2.4), 3);
  const VoronoiMesh mesh = compute_cells(seeds);
  const CellQuality q = measure_cell_quality(mesh);
  const nlohmann::json doc = nlohmann::json::parse(cell_quality_json(q));
  EXPECT_EQ(doc["cells"], mesh.cells.size());
  const auto& ratio = doc["aspect_ratio"];
  EXPECT_EQ(ratio["min"].get<double>(), q.min_aspect_ratio);
  EXPECT_EQ(ratio["mean"].get<double>(), q.mean_aspect_ratio);
  EXPECT_EQ(ratio["max"].get<double>(), q.max_aspect_ratio);
  EXPECT_EQ(ratio["worst_cell"], q.worst_cell);
  EXPECT_EQ(ratio["worst_seed"], mesh.cells[q.worst_cell].seed);
  EXPECT_EQ(ratio["histogram"]["low"], 1.0);
  EXPECT_EQ(ratio["histogram"]["high"], 5.0);
  EXPECT_EQ(ratio["histogram"]["counts"].get<std::vector<std::size_t>>(), q.aspect_ratio_histogram);
  EXPECT_EQ(ratio["histogram"]["above_high"], q.aspect_ratio_above_high);
  EXPECT_NE(ratio["definition"].get<std::string>().find("sqrt(3) for a cube"), std::string::npos);
  EXPECT_EQ(doc["volume"]["total"].get<double>(), q.total_volume);
  EXPECT_EQ(doc["faces"]["min"], q.min_faces);
  EXPECT_EQ(doc["faces"]["max"], q.max_faces);
  EXPECT_EQ(doc["shortest_edge"]["min"].get<double>(), q.min_shortest_edge_relative);
  EXPECT_EQ(doc["layers"]["interior_cells"], q.interior.cells);
  EXPECT_EQ(doc["layers"]["boundary_layer_cells"], q.boundary_layer.cells);
  const auto& short_edges = doc["edge_length"]["interior"];
  EXPECT_EQ(short_edges["min"].get<double>(), q.interior.edge_length.min);
  EXPECT_EQ(short_edges["min_cell"], q.interior.edge_length.min_cell);
  EXPECT_EQ(short_edges["thresholds"][2]["below"].get<double>(), 0.1);
  EXPECT_EQ(short_edges["thresholds"][2]["count"], q.interior.edge_length.below[2]);
  EXPECT_EQ(doc["face_area"]["boundary_layer"]["histogram"]["counts"].get<std::vector<std::size_t>>(),
            q.boundary_layer.face_area.histogram);
  EXPECT_EQ(doc["dihedral_angle"]["boundary_layer"]["max"].get<double>(), q.boundary_layer.dihedral_angle.max);

  // A cell without interior: JSON has no infinity, so null.
  CellQuality flat = q;
  flat.max_aspect_ratio = flat.mean_aspect_ratio = std::numeric_limits<double>::infinity();
  const nlohmann::json flat_doc = nlohmann::json::parse(cell_quality_json(flat));
  EXPECT_TRUE(flat_doc["aspect_ratio"]["max"].is_null());
  EXPECT_TRUE(flat_doc["aspect_ratio"]["mean"].is_null());
  EXPECT_EQ(flat_doc["aspect_ratio"]["min"].get<double>(), q.min_aspect_ratio);

  // quality --json: the cells under "cells", alone or next to the surface figures.
  const nlohmann::json alone = nlohmann::json::parse(quality_json(nullptr, &q));
  EXPECT_EQ(alone.size(), 1u);
  EXPECT_EQ(alone["cells"], doc);
  const SurfaceMesh joint = read_mesh(test::model("cgal_joint.off"));
  QualityOptions few;
  few.random_samples = 100;
  const SurfaceQuality s = measure_surface_quality(joint, joint, few);
  nlohmann::json both = nlohmann::json::parse(quality_json(&s, &q));
  EXPECT_EQ(both["cells"], doc);
  EXPECT_EQ(both["triangles"], 446);
  both.erase("cells");
  EXPECT_EQ(both, nlohmann::json::parse(surface_quality_json(s)));
}

TEST(QualityReport, CellsRunReportStandsAloneOrJoinsAMeshRunsReport) {
  const auto seeds = test::lattice_seeds(6, 0.2, test::ball_region(Point(2.5, 2.5, 2.5), 1.9), 4);
  const VoronoiMesh mesh = compute_cells(seeds);
  const CellQuality q = measure_cell_quality(mesh);
  CellsReport report;
  report.command = {"vorocrust", "cells", "s.csv", "-o", "out"};
  report.seeds_file = "s.csv";
  report.seeds = seeds.size();
  report.mesh = &mesh;
  report.quality = &q;
  report.timings = {{"cells", 0.25}, {"cell quality", 0.5}};
  nlohmann::json doc = nlohmann::json::parse(cells_report_json(report));
  EXPECT_EQ(doc["status"], "ok");
  EXPECT_EQ(doc["seeds"], seeds.size());
  EXPECT_EQ(doc["total_seconds"].get<double>(), 0.75);
  EXPECT_EQ(doc["cells"]["cells"], mesh.cells.size());
  std::size_t interior = 0;
  for (const VoronoiFace& f : mesh.faces) interior += f.neighbour != kNoCell;
  EXPECT_EQ(doc["cells"]["interior_faces"], interior);
  EXPECT_EQ(doc["cells"]["boundary_faces"], mesh.faces.size() - interior);
  EXPECT_EQ(doc["cells"]["quality"], nlohmann::json::parse(cell_quality_json(q)));

  // Over a mesh run's report: everything kept but "cells", which is this run's.
  report.previous = R"({"status": "ok", "inputs": ["m.off"], "cells": {"cells": 1}, "surface": {"triangles": 9}})";
  doc = nlohmann::json::parse(cells_report_json(report));
  EXPECT_EQ(doc["inputs"], nlohmann::json::array({"m.off"}));
  EXPECT_EQ(doc["surface"]["triangles"], 9);
  EXPECT_EQ(doc["cells"]["cells"], mesh.cells.size());
  EXPECT_EQ(doc["cells"]["seeds_file"], "s.csv");
  EXPECT_EQ(doc["cells"]["command"][1], "cells");
  EXPECT_FALSE(doc.contains("seeds_file"));
  const test::TempDir dir("report");
  write_file_atomically(dir / "report.json", doc.dump());
  EXPECT_EQ(run_report_inputs(dir / "report.json"), std::vector<std::string>{"m.off"});

  // Over anything else (an earlier cells report, a broken file): a fresh report.
  for (const char* previous : {R"({"status": "ok", "seeds_file": "old.csv"})", "{\"inputs\": ["}) {
    report.previous = previous;
    doc = nlohmann::json::parse(cells_report_json(report));
    EXPECT_EQ(doc["seeds_file"], "s.csv") << previous;
    EXPECT_FALSE(doc.contains("inputs")) << previous;
  }
}

TEST(QualityReport, TimingsHoldOneEntryPerPhaseWithItsRunsAndPeak) {
  RunReport report;
  report.status = "invalid geometry";
  report.timings = {{"reading", 0.5, 100},
                    {"refinement: creases", 1, 300},
                    {"refinement: patches", 2, 400},
                    {"refinement: creases, pass 2", 0.25, 500},
                    {"refinement: patches, pass 2", 0.5, 600},
                    {"skew repair", 0.125, 700},
                    {"skew repair", 0.125, 800}};
  const nlohmann::json doc = nlohmann::json::parse(run_report_json(report));
  // A phase's peak is the process's at the end of its last run, the highest of its runs.
  const nlohmann::json expected = nlohmann::json::parse(R"([
    {"phase": "reading", "seconds": 0.5, "runs": 1, "peak_resident_bytes": 100},
    {"phase": "refinement: creases", "seconds": 1.25, "runs": 2, "peak_resident_bytes": 500},
    {"phase": "refinement: patches", "seconds": 2.5, "runs": 2, "peak_resident_bytes": 600},
    {"phase": "skew repair", "seconds": 0.25, "runs": 2, "peak_resident_bytes": 800}])");
  EXPECT_EQ(doc["timings"], expected);
  EXPECT_EQ(doc["total_seconds"].get<double>(), 4.5);
}

TEST(QualityReport, InputsComeBackFromReportJson) {
  const test::TempDir dir("report");
  write_file_atomically(dir / "report.json", R"({"status": "ok", "inputs": ["a.obj", "/models/b.off"]})");
  EXPECT_EQ(run_report_inputs(dir / "report.json"), (std::vector<std::string>{"a.obj", "/models/b.off"}));
}

TEST(QualityReport, BadReportJsonIsUnreadableInputNamingIt) {
  const test::TempDir dir("report");
  const auto expect_failure = [&](const std::string& content, const std::string& phrase) {
    const auto path = dir / "report.json";
    if (content.empty()) {
      std::filesystem::remove(path);
    } else {
      write_file_atomically(path, content);
    }
    try {
      run_report_inputs(path);
      ADD_FAILURE() << "no error for " << content;
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::UnreadableInput);
      EXPECT_EQ(e.where().file, path.string());
      EXPECT_NE(e.message().find(phrase), std::string::npos) << e.message();
    }
  };
  expect_failure("", "no such file");
  expect_failure("{\"inputs\": [", "not a JSON document");
  expect_failure("{\"status\": \"ok\"}", "no 'inputs' list");
  expect_failure("[1, 2]", "no 'inputs' list");
  expect_failure("{\"inputs\": [3]}", "other than file names");
}

}  // namespace
}  // namespace vorocrust
