// The surface-quality JSON and reading a run's inputs back from its report.json.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

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
