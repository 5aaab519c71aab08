// vorocrust/report_html.hpp — OUTDIR/report.html: a mesh run to look at, in one file that any
// browser opens from disk with no network.
//
// Contract of report_html(result, page):
// - Sections, each table with an id: the run (page.summary's lines, id "summary"; page.warnings
//   listed under it), the regions (id "regions": a row per region the input cuts out, with its
//   cells, the cells' volume and the volume the input and the output surface enclose), the
//   surface's quality (id "surface-quality"), the cells' quality (id "cell-quality"), the worst
//   cells by aspect ratio (id "worst-cells": the 20 worst, or all when fewer, worst first) and
//   the time of each phase (id "timings", from page.timings).
// - Pictures, as PNG data URIs (8-bit RGB, 720 x 540), flat shaded, seen without perspective:
//   the output surface coloured by region (id "surface-picture"); the cells on the far side of
//   a plane across the thinnest extent of the mesh through its middle, coloured by material,
//   the cells the plane cuts sticking out whole (id "cut-picture"), its caption naming the plane
//   and the cells it cuts; the worst cells in red over the faint surface
//   (id "worst-cells-picture"); and quality.svg's histograms as an SVG data URI
//   (id "histograms").
// - A run that stopped before the cells has the surface's sections only, and says so.
// - Numbers are written the same whatever the program's locale; text from the input (region
//   names, file names) is escaped.
// Requires result.surface_quality (a run that reached Stage::Surface); Error(Usage) otherwise.
// write_report_html writes the page atomically (atomic_file.hpp); Error(Output) when it cannot.
#pragma once

#include "vorocrust/api.hpp"

#include <filesystem>
#include <string>
#include <vector>

#include "vorocrust/mesh_result.hpp"
#include "vorocrust/stats.hpp"

namespace vorocrust {

struct VOROCRUST_API ReportPage {
  std::string title;                  // the page's heading: the model's name
  std::vector<std::string> summary;   // the run's figures, a line each (JobResult::summary)
  std::vector<std::string> warnings;  // JobResult::warnings
  std::vector<PhaseTiming> timings;
};

VOROCRUST_API std::string report_html(const MeshResult& result, const ReportPage& page);

VOROCRUST_API void write_report_html(const std::filesystem::path& path, const MeshResult& result,
                                     const ReportPage& page);

// The cut picture alone, as PNG bytes (what the FreeCAD workbench shows after a run);
// Error(Usage) for a result without cells.
VOROCRUST_API std::string cut_picture_png(const MeshResult& result, int width = 720, int height = 540);

}  // namespace vorocrust
