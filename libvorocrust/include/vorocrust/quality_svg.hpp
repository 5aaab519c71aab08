// vorocrust/quality_svg.hpp — histograms drawn as one standalone SVG picture, as
// OUTDIR/quality.svg shows the triangle quality of the surface and the aspect ratio of the cells.
//
// Panels stack top to bottom under the title. Each draws its bins as bars over an x axis from
// `low` to `high`, with ticks on both axes, every non-empty bin's count above its bar (and at
// least a hairline of bar, so a handful of bad elements among thousands still shows), and the
// minimum and the mean marked by labelled vertical lines (at the axis end when beyond it). A
// panel with an overflow count draws it as one more bar past `high`, in another colour, labelled
// "> high". Numbers are written the same whatever the program's locale.
#pragma once

#include "vorocrust/api.hpp"

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "vorocrust/cell_quality.hpp"
#include "vorocrust/quality.hpp"

namespace vorocrust {

struct VOROCRUST_API HistogramPanel {
  std::string label;                // what is counted, with its unit: "triangle quality Q"
  double low = 0, high = 1;         // the bins split [low, high] evenly
  std::vector<std::size_t> counts;  // one per bin, at least one bin
  double min = 0, mean = 0;         // of the values counted, marked on the axis
  std::optional<std::size_t> above_high;  // values above `high`, when the bins do not reach them all
};

// The triangle-quality panel of OUTDIR/quality.svg.
VOROCRUST_API HistogramPanel surface_quality_panel(const SurfaceQuality& quality);

// The cell aspect-ratio panel of OUTDIR/quality.svg, with the cells above its range as overflow.
VOROCRUST_API HistogramPanel cell_quality_panel(const CellQuality& quality);

// The panels of the cells' edge lengths and face areas against the cell size (the cube root of its
// volume) and of their dihedral angles (cell_quality.hpp), each for the boundary layer and the
// interior where that layer has cells.
VOROCRUST_API std::vector<HistogramPanel> cell_part_panels(const CellQuality& quality);

// The panels of quality.svg: the surface's, then the cells' (aspect ratio, then their parts), each
// where its quality is given.
VOROCRUST_API std::vector<HistogramPanel> quality_panels(const std::optional<SurfaceQuality>& surface,
                                                         const std::optional<CellQuality>& cells);

// The picture as text. Throws Error(Usage) for a panel without bins or with high <= low.
VOROCRUST_API std::string histogram_svg(const std::string& title, const std::vector<HistogramPanel>& panels);

// The same, written atomically to `path` (atomic_file.hpp); throws Error(Output) when it cannot be.
VOROCRUST_API void write_histogram_svg(const std::filesystem::path& path, const std::string& title,
                         const std::vector<HistogramPanel>& panels);

}  // namespace vorocrust
