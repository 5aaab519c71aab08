// report.html: a real run's page holds every table and picture, with the run's own figures.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "report/markup.hpp"
#include "report/png_reader.hpp"
#include "test_support.hpp"
#include "vorocrust/atomic_file.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/job.hpp"

namespace vorocrust {
namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The text of the element with `id` up to its closing tag.
std::string element(const std::string& html, const std::string& id, const std::string& tag) {
  const std::size_t start = html.find("id=\"" + id + "\"");
  if (start == std::string::npos) return {};
  const std::size_t end = html.find("</" + tag + ">", start);
  return html.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

// The PNG of an <img id=...>'s data URI, decoded.
test::DecodedPng picture(const std::string& html, const std::string& id) {
  const std::string img = element(html, id, "figure");
  const std::string prefix = "src=\"data:image/png;base64,";
  const std::size_t at = img.find(prefix);
  if (at == std::string::npos) {
    ADD_FAILURE() << id << " has no PNG data URI";
    return {};
  }
  const std::size_t begin = at + prefix.size();
  return test::decode_png(test::decode_base64(img.substr(begin, img.find('"', begin) - begin)));
}

// Of the sampled pixels, the share that is not the white background.
double drawn_share(const test::DecodedPng& png) {
  std::size_t drawn = 0, seen = 0;
  for (std::size_t i = 0; i + 2 < png.rgb.size(); i += 3 * 7, ++seen) {
    if (png.rgb[i] != 255 || png.rgb[i + 1] != 255 || png.rgb[i + 2] != 255) ++drawn;
  }
  return seen ? static_cast<double>(drawn) / static_cast<double>(seen) : 0;
}

class ReportHtml : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::TempDir("report-html");
    job_ = new Job;
    job_->inputs = {test::model("sandia_non_manifold_box.obj")};
    job_->options.seed = 1;
    job_->options.threads = 2;
    job_->options.formats = {OutputFormat::ReportHtml};
    job_->output_dir = dir_->path() / "out";
    result_ = new JobResult(run_job(*job_));
    html_ = new std::string(read_text(job_->output_dir / "report.html"));
  }
  static void TearDownTestSuite() {
    delete html_;
    delete result_;
    delete job_;
    delete dir_;
  }
  static test::TempDir* dir_;
  static Job* job_;
  static JobResult* result_;
  static std::string* html_;
};
test::TempDir* ReportHtml::dir_ = nullptr;
Job* ReportHtml::job_ = nullptr;
JobResult* ReportHtml::result_ = nullptr;
std::string* ReportHtml::html_ = nullptr;

TEST_F(ReportHtml, IsWrittenBesideReportJsonAndNothingElse) {
  const std::vector<std::filesystem::path> expected = {job_->output_dir / "report.html",
                                                       job_->output_dir / "report.json"};
  EXPECT_EQ(result_->written, expected);
  EXPECT_TRUE(html_->starts_with("<!DOCTYPE html>"));
  EXPECT_TRUE(html_->ends_with("</html>\n"));
  // Nothing to fetch: no script, no style sheet or picture from elsewhere.
  EXPECT_EQ(html_->find("<script"), std::string::npos);
  EXPECT_EQ(html_->find("http"), std::string::npos);
}

TEST_F(ReportHtml, HoldsEveryTableWithTheRunsFigures) {
  for (const char* id :
       {"summary", "regions", "surface-quality", "cell-quality", "cell-parts", "worst-cells", "timings"}) {
    EXPECT_FALSE(element(*html_, id, "table").empty()) << id;
  }
  const std::string summary = element(*html_, "summary", "table");
  ASSERT_FALSE(result_->summary.empty());
  for (const std::string& line : result_->summary) {
    EXPECT_NE(summary.find(report::escape_markup(line)), std::string::npos) << line;
  }
  const MeshResult& mesh = result_->mesh;
  const std::string regions = element(*html_, "regions", "table");
  EXPECT_EQ(test::occurrences(regions, "<tr>"), 1 + mesh.regions.size());
  for (const RegionSummary& r : mesh.regions) EXPECT_NE(regions.find(report::escape_markup(r.name)), std::string::npos);

  // The worst cells, worst first, as the cell quality found them.
  const CellQuality& quality = *mesh.cell_quality;
  const std::string worst = element(*html_, "worst-cells", "table");
  ASSERT_EQ(test::occurrences(worst, "<tr>"), 1 + std::min<std::size_t>(20, mesh.cells.cells.size()));
  const std::string first_row = "<tr><td>1</td><td class=\"n\">" + std::to_string(quality.worst_cell) +
                                "</td><td class=\"n\">" + std::to_string(quality.worst_seed) + "</td>";
  EXPECT_NE(worst.find(first_row), std::string::npos) << worst.substr(0, 400);
  EXPECT_NE(element(*html_, "cell-quality", "table").find(report::locale_free_number(quality.max_aspect_ratio, std::chars_format::general, 4)),
            std::string::npos);
  // The short edges by layer: three measures for each layer with cells.
  const std::string parts = element(*html_, "cell-parts", "table");
  EXPECT_EQ(test::occurrences(parts, "<tr>"), 1 + 3 * ((quality.boundary_layer.cells > 0) + (quality.interior.cells > 0)));
  EXPECT_NE(parts.find(report::locale_free_number(quality.boundary_layer.edge_length.min, std::chars_format::general, 4)),
            std::string::npos);
}

TEST_F(ReportHtml, PicturesDecodeAndShowTheMesh) {
  for (const char* id : {"surface-picture", "cut-picture", "worst-cells-picture"}) {
    const test::DecodedPng png = picture(*html_, id);
    EXPECT_EQ(png.width, 720) << id;
    EXPECT_EQ(png.height, 540) << id;
    EXPECT_EQ(png.rgb.size(), 720u * 540 * 3) << id;
    EXPECT_GT(drawn_share(png), 0.05) << id << " is nearly empty";
  }
  EXPECT_NE(html_->find("id=\"histograms\" src=\"data:image/svg+xml;base64,"), std::string::npos);
  // The cut picture alone, as the FreeCAD workbench shows it, is the page's.
  const test::DecodedPng cut = picture(*html_, "cut-picture");
  EXPECT_EQ(cut.rgb, test::decode_png(cut_picture_png(result_->mesh)).rgb);
}

TEST_F(ReportHtml, TheCutCaptionCountsTheCellsThePlaneCrosses) {
  const VoronoiMesh& cells = result_->mesh.cells;
  Point low = Point::Constant(1e300), high = Point::Constant(-1e300);
  for (const Point& p : cells.points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  int axis = 0;
  (high - low).minCoeff(&axis);
  const double at = (low[axis] + high[axis]) / 2;
  std::size_t crossed = 0;
  for (const VoronoiCell& cell : cells.cells) {
    bool below = false, above = false;
    for (Index f : cell.faces) {
      for (Index p : cells.faces[f].points) {
        below |= cells.points[p][axis] < at;
        above |= cells.points[p][axis] > at;
      }
    }
    crossed += below && above;
  }
  ASSERT_GT(crossed, 0u);
  const std::string caption = std::to_string(crossed) + " cells cut by the plane " + "xyz"[axis] + " = ";
  EXPECT_NE(element(*html_, "cut-picture", "figure").find(caption), std::string::npos) << caption;
}

TEST(ReportHtmlStages, ARunWithoutCellsHasTheSurfaceAloneAndSaysSo) {
  const test::TempDir dir("report-html-surface");
  Job job;
  job.inputs = {test::model("sandia_non_manifold_box.obj")};
  job.options.seed = 1;
  job.options.stop_after = Stage::Surface;
  job.options.formats = {OutputFormat::ReportHtml};
  job.output_dir = dir.path();
  const JobResult result = run_job(job);
  const std::string html = read_text(dir / "report.html");
  EXPECT_NE(html.find("The run stopped before the cells."), std::string::npos);
  EXPECT_EQ(picture(html, "surface-picture").width, 720);
  for (const char* id : {"cut-picture", "worst-cells-picture", "cell-quality", "worst-cells"}) {
    EXPECT_EQ(html.find(std::string("id=\"") + id + "\""), std::string::npos) << id;
  }
  EXPECT_THROW(cut_picture_png(result.mesh), Error);
  // Before the surface there is nothing to show: refused by name.
  MeshResult balls_only;
  try {
    (void)report_html(balls_only, {});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Usage);
    EXPECT_NE(std::string(e.what()).find("report.html"), std::string::npos);
  }
}

TEST(ReportHtmlStages, Base64RoundTrips) {
  std::string bytes;
  for (int i = 0; i < 256; ++i) bytes += static_cast<char>(i);
  for (std::size_t n : {0, 1, 2, 3, 255, 256}) {
    EXPECT_EQ(test::decode_base64(report::base64(std::string_view(bytes).substr(0, n))), bytes.substr(0, n));
  }
}

}  // namespace
}  // namespace vorocrust
