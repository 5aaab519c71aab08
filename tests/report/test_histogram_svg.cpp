// The histogram picture: what it must show, escaped, stacked and written whole.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>

#include "cells/seed_sets.hpp"
#include "test_support.hpp"
#include "vorocrust/cell_quality.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/quality_svg.hpp"

namespace vorocrust {
namespace {

HistogramPanel quality_panel() {
  HistogramPanel p;
  p.label = "triangle quality Q";
  p.counts = std::vector<std::size_t>(20, 0);
  p.counts[3] = 2;  // two bad triangles among thousands must still show
  p.counts[16] = 800;
  p.counts[17] = 4000;
  p.counts[19] = 1200;
  p.min = 0.17;
  p.mean = 0.86;
  return p;
}

TEST(HistogramSvg, DrawsEveryNonEmptyBinWithItsCountAndMarksMinAndMean) {
  const std::string svg = histogram_svg("surface quality", {quality_panel()});
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_EQ(test::occurrences(svg, "fill=\"#4a7fb5\""), 4u);  // one bar per non-empty bin
  for (const char* count : {">2<", ">800<", ">4000<", ">1200<"}) EXPECT_NE(svg.find(count), std::string::npos) << count;
  EXPECT_NE(svg.find(">min 0.17<"), std::string::npos);
  EXPECT_NE(svg.find(">mean 0.86<"), std::string::npos);
  EXPECT_NE(svg.find(">6002 in 20 bins<"), std::string::npos);
  for (const char* tick : {">0<", ">0.5<", ">1<", ">5000<"}) EXPECT_NE(svg.find(tick), std::string::npos) << tick;
  EXPECT_EQ(svg.find("e+"), std::string::npos);  // counts are whole numbers, never 5e+03
  // The smallest bar is at least a hairline high.
  const std::regex bar("<rect x=\"[0-9.]+\" y=\"[0-9.]+\" width=\"[0-9.]+\" height=\"([0-9.]+)\" fill=\"#4a7fb5\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), bar); it != std::sregex_iterator(); ++it)
    EXPECT_GE(std::stod((*it)[1]), 1.0);
}

TEST(HistogramSvg, StacksPanelsAndEscapesText) {
  HistogramPanel second = quality_panel();
  second.label = "cell aspect ratio <circumradius & inradius>";
  second.low = 1;
  second.high = 11;
  const std::string svg = histogram_svg("a \"title\"", {quality_panel(), second});
  EXPECT_NE(svg.find("cell aspect ratio &lt;circumradius &amp; inradius&gt;"), std::string::npos);
  EXPECT_NE(svg.find("a &quot;title&quot;"), std::string::npos);
  EXPECT_EQ(svg.find("<circumradius"), std::string::npos);
  EXPECT_NE(svg.find("height=\"600.0\""), std::string::npos);  // title and two panels
  EXPECT_NE(svg.find(">11<"), std::string::npos);
}

TEST(HistogramSvg, OverflowIsOneMoreBarPastTheRange) {
  HistogramPanel p = quality_panel();
  p.low = 1;
  p.high = 5;
  p.min = 1.3;
  p.mean = 7;  // beyond the axis: its line at the axis end, its label saying the value
  p.above_high = 37;
  const std::string svg = histogram_svg("cells", {p});
  EXPECT_EQ(test::occurrences(svg, "fill=\"#4a7fb5\""), 4u);
  EXPECT_EQ(test::occurrences(svg, "fill=\"#b5834a\""), 1u);  // the overflow bar
  EXPECT_NE(svg.find(">37<"), std::string::npos);
  EXPECT_NE(svg.find(">&gt; 5<"), std::string::npos);
  EXPECT_NE(svg.find(">6002 in 20 bins, 37 above 5<"), std::string::npos);
  EXPECT_NE(svg.find(">mean 7<"), std::string::npos);
  // Twenty-one slots of (720 - 70 - 24) / 21 units: the last bin ends where the overflow begins.
  const double slot = (720.0 - 70 - 24) / 21;
  char edge[32];
  std::snprintf(edge, sizeof edge, "<rect x=\"%.1f\"", 70 + 20 * slot + 1);
  EXPECT_NE(svg.find(edge), std::string::npos) << edge;
  // An empty overflow draws no bar but still says there is none above.
  p.above_high = 0;
  const std::string none = histogram_svg("cells", {p});
  EXPECT_EQ(test::occurrences(none, "fill=\"#b5834a\""), 0u);
  EXPECT_NE(none.find(">6002 in 20 bins, 0 above 5<"), std::string::npos);
}

// quality.svg of a run with cells: the surface panel and the aspect-ratio panel, one under the other.
TEST(HistogramSvg, SurfaceAndCellPanelsTogether) {
  const auto seeds = test::lattice_seeds(8, 0.3, test::ball_region(Point(3.5, 3.5, 3.5), 2.9), 6);
  CellQualityOptions options;
  options.histogram_high = 2;  // so that some jittered cells overflow
  const CellQuality cells = measure_cell_quality(compute_cells(seeds), options);
  ASSERT_GT(cells.aspect_ratio_above_high, 0u);
  const HistogramPanel panel = cell_quality_panel(cells);
  EXPECT_EQ(panel.counts, cells.aspect_ratio_histogram);
  EXPECT_EQ(panel.low, 1);
  EXPECT_EQ(panel.high, 2);
  EXPECT_EQ(panel.above_high, cells.aspect_ratio_above_high);
  EXPECT_EQ(panel.min, cells.min_aspect_ratio);
  EXPECT_EQ(panel.mean, cells.mean_aspect_ratio);

  const std::string svg = histogram_svg("surface and cell quality", {quality_panel(), panel});
  EXPECT_NE(svg.find(">triangle quality Q<"), std::string::npos);
  EXPECT_NE(svg.find(">cell aspect ratio R / r (circumradius over inradius)<"), std::string::npos);
  EXPECT_NE(svg.find("height=\"600.0\""), std::string::npos);
  const std::size_t binned = cells.cells.size() - cells.aspect_ratio_above_high;
  EXPECT_NE(svg.find(">" + std::to_string(binned) + " in 16 bins, " + std::to_string(cells.aspect_ratio_above_high) +
                     " above 2<"),
            std::string::npos);
  EXPECT_EQ(test::occurrences(svg, ">min "), 2u);
  EXPECT_EQ(test::occurrences(svg, ">mean "), 2u);
}

// The cells' parts: edges, faces and dihedral angles, each for the boundary layer and the
// interior; a layer without cells gets no panel.
TEST(HistogramSvg, CellPartPanelsByLayer) {
  const auto seeds = test::lattice_seeds(8, 0.3, test::ball_region(Point(3.5, 3.5, 3.5), 2.9), 6);
  const CellQuality cells = measure_cell_quality(compute_cells(seeds));
  const std::vector<HistogramPanel> panels = cell_part_panels(cells);
  ASSERT_EQ(panels.size(), 6u);
  EXPECT_EQ(panels[0].label, "edge length / cell size, boundary layer (" +
                                 std::to_string(cells.boundary_layer.cells) + " cells)");
  EXPECT_EQ(panels[0].counts, cells.boundary_layer.edge_length.histogram);
  EXPECT_EQ(panels[1].min, cells.interior.edge_length.min);
  EXPECT_EQ(panels[3].above_high, cells.interior.face_area.above_high);
  EXPECT_EQ(panels[5].mean, cells.interior.dihedral_angle.mean);
  EXPECT_EQ(quality_panels(std::nullopt, cells).size(), 7u);

  CellQuality no_interior = cells;
  no_interior.interior = {};
  EXPECT_EQ(cell_part_panels(no_interior).size(), 3u);
}

TEST(HistogramSvg, RefusesPanelsWithoutBinsOrRange) {
  HistogramPanel empty = quality_panel();
  empty.counts.clear();
  EXPECT_THROW(histogram_svg("q", {empty}), Error);
  HistogramPanel flat = quality_panel();
  flat.high = flat.low;
  EXPECT_THROW(histogram_svg("q", {flat}), Error);
}

TEST(HistogramSvg, WritesTheFileAtomically) {
  const test::TempDir dir("svg");
  write_histogram_svg(dir / "quality.svg", "q", {quality_panel()});
  std::ifstream in(dir / "quality.svg");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), histogram_svg("q", {quality_panel()}));
  EXPECT_THROW(write_histogram_svg(dir / "missing" / "quality.svg", "q", {quality_panel()}), Error);
}

}  // namespace
}  // namespace vorocrust
