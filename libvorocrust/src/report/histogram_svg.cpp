// Histograms as SVG: plain shapes and text, no script or style sheet, so any viewer shows them.
#include <algorithm>
#include <cmath>
#include <locale>
#include <numeric>
#include <sstream>

#include "report/markup.hpp"
#include "vorocrust/atomic_file.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/cell_quality.hpp"
#include "vorocrust/quality.hpp"
#include "vorocrust/quality_svg.hpp"

namespace vorocrust {

namespace {

// Page and panel geometry, in SVG user units (pixels).
constexpr double kWidth = 720, kTitleHeight = 40, kPanelHeight = 280;
constexpr double kLeft = 70, kRight = 24, kTop = 56, kBottom = 48;  // plot margins inside a panel

std::string coordinate(double x) { return report::locale_free_number(x, std::chars_format::fixed, 1); }
std::string value(double x) { return report::locale_free_number(x, std::chars_format::general, 4); }
std::string escaped(const std::string& text) { return report::escape_markup(text); }

// The smallest of 1, 2, 5 times a power of ten that is at least x (x > 0).
double nice_step(double x) {
  const double power = std::pow(10.0, std::floor(std::log10(x)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * power >= x) return m * power;
  return 10 * power;
}

void check(const HistogramPanel& panel) {
  if (panel.counts.empty()) throw Error(Error::Kind::Usage, "histogram '" + panel.label + "' has no bins");
  if (!(panel.high > panel.low)) {
    throw Error(Error::Kind::Usage, "histogram '" + panel.label + "' needs low < high, got " + value(panel.low) +
                                        " and " + value(panel.high));
  }
}

void draw_panel(std::ostream& svg, const HistogramPanel& panel, double top) {
  const double x0 = kLeft, x1 = kWidth - kRight, y0 = top + kPanelHeight - kBottom, y1 = top + kTop;
  const std::size_t bins = panel.counts.size();
  // The overflow bar, if any, is one more slot after the bins.
  std::vector<std::size_t> bars = panel.counts;
  if (panel.above_high) bars.push_back(*panel.above_high);
  const std::size_t binned = std::accumulate(panel.counts.begin(), panel.counts.end(), std::size_t{0});
  const std::size_t largest = *std::max_element(bars.begin(), bars.end());
  const double step = nice_step(std::max<double>(1, static_cast<double>(largest) / 4));
  // Headroom above the tallest bar for its count.
  const double y_max = step * std::max(1.0, std::ceil(1.1 * static_cast<double>(largest) / step));
  const double bar = (x1 - x0) / static_cast<double>(bars.size());
  const double x_high = x0 + bar * static_cast<double>(bins);
  const auto x_of = [&](double v) {
    return x0 + (x_high - x0) * std::clamp((v - panel.low) / (panel.high - panel.low), 0.0, 1.0);
  };
  const auto y_of = [&](double count) { return y0 - (y0 - y1) * count / y_max; };

  svg << "<text x=\"" << coordinate(x0) << "\" y=\"" << coordinate(top + 24) << "\" font-size=\"15\">"
      << escaped(panel.label) << "</text>\n";
  svg << "<text x=\"" << coordinate(x1) << "\" y=\"" << coordinate(top + 24)
      << "\" font-size=\"12\" text-anchor=\"end\" fill=\"#555\">" << binned << " in " << bins << " bins";
  if (panel.above_high) svg << ", " << *panel.above_high << " above " << value(panel.high);
  svg << "</text>\n";

  // Bars, each non-empty one at least a hairline high, with its count above it where it fits.
  for (std::size_t k = 0; k < bars.size(); ++k) {
    const std::size_t n = bars[k];
    if (n == 0) continue;
    const double y = std::min(y_of(static_cast<double>(n)), y0 - 1.0);
    svg << "<rect x=\"" << coordinate(x0 + bar * static_cast<double>(k) + 1) << "\" y=\"" << coordinate(y)
        << "\" width=\"" << coordinate(std::max(1.0, bar - 2)) << "\" height=\"" << coordinate(y0 - y)
        << "\" fill=\"" << (k < bins ? "#4a7fb5" : "#b5834a") << "\"/>\n";
    if (bar >= 5.5 * static_cast<double>(std::to_string(n).size()) + 2) {  // digits about 5.5 wide at size 9
      svg << "<text x=\"" << coordinate(x0 + bar * (static_cast<double>(k) + 0.5)) << "\" y=\""
          << coordinate(y - 3) << "\" font-size=\"9\" text-anchor=\"middle\">" << n << "</text>\n";
    }
  }

  // Axes and ticks: counts on the left (whole numbers, the step being one at least), bin edges
  // below (about ten labelled).
  svg << "<path d=\"M" << coordinate(x0) << ' ' << coordinate(y1) << " V" << coordinate(y0) << " H" << coordinate(x1)
      << "\" stroke=\"#333\" fill=\"none\"/>\n";
  for (double c = 0; c <= y_max * (1 + 1e-9); c += step) {
    const double y = y_of(c);
    svg << "<path d=\"M" << coordinate(x0 - 5) << ' ' << coordinate(y) << " H" << coordinate(x0)
        << "\" stroke=\"#333\"/>\n<text x=\"" << coordinate(x0 - 8) << "\" y=\"" << coordinate(y + 4)
        << "\" font-size=\"11\" text-anchor=\"end\">" << static_cast<std::size_t>(c) << "</text>\n";
  }
  const std::size_t every = (bins + 9) / 10;
  for (std::size_t k = 0; k <= bins; k += every) {
    const double x = x0 + bar * static_cast<double>(k);
    const double edge = panel.low + (panel.high - panel.low) * static_cast<double>(k) / static_cast<double>(bins);
    svg << "<path d=\"M" << coordinate(x) << ' ' << coordinate(y0) << " V" << coordinate(y0 + 5)
        << "\" stroke=\"#333\"/>\n<text x=\"" << coordinate(x) << "\" y=\"" << coordinate(y0 + 18)
        << "\" font-size=\"11\" text-anchor=\"middle\">" << value(edge) << "</text>\n";
  }
  if (panel.above_high) {
    // Below the tick labels, clear of the label of `high` next to it.
    svg << "<text x=\"" << coordinate(x_high + bar / 2) << "\" y=\"" << coordinate(y0 + 32)
        << "\" font-size=\"11\" text-anchor=\"middle\">&gt; " << value(panel.high) << "</text>\n";
  }

  // The minimum labelled to the left of its line and the mean to the right, so the labels stay
  // apart when the lines nearly meet; a label that would leave the page goes to the other side.
  const auto mark = [&](double v, const std::string& name, const char* colour, bool left) {
    const double x = x_of(v);
    const std::string text = name + ' ' + value(v);
    const double width = 6.5 * static_cast<double>(text.size());  // about, at 11 units
    if (left && x - width < 4) left = false;
    if (!left && x + width > kWidth - 4) left = true;
    svg << "<path d=\"M" << coordinate(x) << ' ' << coordinate(y1 - 6) << " V" << coordinate(y0)
        << "\" stroke=\"" << colour << "\" stroke-width=\"1.5\" stroke-dasharray=\"5 3\"/>\n<text x=\""
        << coordinate(left ? x - 3 : x + 3) << "\" y=\"" << coordinate(y1 - 8) << "\" font-size=\"11\" fill=\""
        << colour << "\" text-anchor=\"" << (left ? "end" : "start") << "\">" << escaped(text) << "</text>\n";
  };
  mark(panel.min, "min", "#c0392b", true);
  mark(panel.mean, "mean", "#1e8449", false);
}

}  // namespace

std::string histogram_svg(const std::string& title, const std::vector<HistogramPanel>& panels) {
  for (const HistogramPanel& panel : panels) check(panel);
  const double height = kTitleHeight + kPanelHeight * static_cast<double>(panels.size());
  std::ostringstream svg;
  svg.imbue(std::locale::classic());  // counts without thousands separators, whatever the global locale
  svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\""
      << coordinate(kWidth) << "\" height=\"" << coordinate(height) << "\" viewBox=\"0 0 " << coordinate(kWidth)
      << ' ' << coordinate(height) << "\" font-family=\"sans-serif\">\n<title>" << escaped(title) << "</title>\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<text x=\"" << coordinate(kWidth / 2)
      << "\" y=\"26\" font-size=\"17\" text-anchor=\"middle\">" << escaped(title) << "</text>\n";
  for (std::size_t i = 0; i < panels.size(); ++i) {
    draw_panel(svg, panels[i], kTitleHeight + kPanelHeight * static_cast<double>(i));
  }
  svg << "</svg>\n";
  return svg.str();
}

void write_histogram_svg(const std::filesystem::path& path, const std::string& title,
                         const std::vector<HistogramPanel>& panels) {
  write_file_atomically(path, histogram_svg(title, panels));
}

HistogramPanel surface_quality_panel(const SurfaceQuality& quality) {
  HistogramPanel panel;
  panel.label = "triangle quality Q = 6S / (sqrt(3) h p) of the output surface";
  panel.counts = quality.quality_histogram;
  panel.min = quality.min_quality;
  panel.mean = quality.mean_quality;
  return panel;
}

HistogramPanel cell_quality_panel(const CellQuality& quality) {
  HistogramPanel panel;
  panel.label = "cell aspect ratio R / r (circumradius over inradius)";
  panel.low = quality.histogram_low;
  panel.high = quality.histogram_high;
  panel.counts = quality.aspect_ratio_histogram;
  panel.min = quality.min_aspect_ratio;
  panel.mean = quality.mean_aspect_ratio;
  panel.above_high = quality.aspect_ratio_above_high;
  return panel;
}

std::vector<HistogramPanel> cell_part_panels(const CellQuality& quality) {
  std::vector<HistogramPanel> panels;
  const auto add = [&](const char* measure, PartDistribution LayerParts::*part) {
    for (const LayerParts* layer : quality.layers()) {
      const PartDistribution& d = layer->*part;
      if (d.count == 0) continue;
      panels.push_back({std::string(measure) + ", " + layer->name + " (" + std::to_string(layer->cells) + " cells)", d.low,
                        d.high, d.histogram, d.min, d.mean, d.above_high});
    }
  };
  add("edge length / cell size", &LayerParts::edge_length);
  add("face area / cell size squared", &LayerParts::face_area);
  add("dihedral angle (degrees)", &LayerParts::dihedral_angle);
  return panels;
}

std::vector<HistogramPanel> quality_panels(const std::optional<SurfaceQuality>& surface,
                                           const std::optional<CellQuality>& cells) {
  std::vector<HistogramPanel> panels;
  if (surface) panels.push_back(surface_quality_panel(*surface));
  if (cells) {
    panels.push_back(cell_quality_panel(*cells));
    for (HistogramPanel& panel : cell_part_panels(*cells)) panels.push_back(std::move(panel));
  }
  return panels;
}

}  // namespace vorocrust
