// OUTDIR/report.html: the run's figures, tables and pictures in one page that opens from disk.
#include "vorocrust/report_html.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <limits>
#include <sstream>

#include "report/markup.hpp"
#include "report/picture.hpp"
#include "vorocrust/atomic_file.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/quality_svg.hpp"

namespace vorocrust {

namespace {

using report::Picture;
using report::Rgb;
using report::View;

constexpr int kPictureWidth = 720, kPictureHeight = 540;
constexpr std::size_t kWorstCells = 20;
constexpr Rgb kBackground{255, 255, 255};

std::string figure(double x) { return report::locale_free_number(x, std::chars_format::general, 4); }
std::string count(std::size_t n) { return std::to_string(n); }
std::string text(std::string_view s) { return report::escape_markup(s); }

using Box = Eigen::AlignedBox3d;

Box bounds(const std::vector<Point>& points) {
  Box box;
  for (const Point& p : points) box.extend(p);
  return box;
}

// Looking down on the model from the front right, the way most meshes are first shown.
View three_quarter_view(const Box& box, int width, int height) {
  return View(box.min(), box.max(), Point(-1, 1.5, -1), Point(0, 0, 1), width, height);
}

// A convex polygon, filled as a fan about its first point, shaded by its normal, with its edges
// drawn in a darker tone when `edges`.
void draw_polygon(Picture& picture, const View& view, const std::vector<Point>& corners, Rgb colour, bool edges) {
  if (corners.size() < 3) return;
  Point normal = Point::Zero();
  for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
    normal += (corners[i] - corners[0]).cross(corners[i + 1] - corners[0]);
  }
  if (!(normal.norm() > 0)) return;
  const Rgb shaded = report::scaled(colour, view.shade(normal.normalized()));
  std::vector<Point> screen;
  screen.reserve(corners.size());
  for (const Point& p : corners) screen.push_back(view.to_screen(p));
  for (std::size_t i = 1; i + 1 < screen.size(); ++i) picture.draw_triangle({screen[0], screen[i], screen[i + 1]}, shaded);
  if (!edges) return;
  const Rgb edge = report::scaled(shaded, 0.55);
  for (std::size_t i = 0; i < screen.size(); ++i) picture.draw_line(screen[i], screen[(i + 1) % screen.size()], edge);
}

// The region a viewer sees on a surface face: the one on the side facing the viewer, unless that
// is the outside.
std::int32_t seen_region(const SurfaceMesh& surface, std::size_t face, const Point& normal, const View& view) {
  if (!surface.has_regions()) return 1;
  const RegionPair& pair = surface.face_regions[face];
  const bool front_seen = normal.dot(view.forward()) < 0;
  const std::int32_t near = front_seen ? pair.front : pair.back, far = front_seen ? pair.back : pair.front;
  return near > 0 ? near : far;
}

// Edges drawn only where faces are large enough on the picture for them not to hide the faces.
bool edges_show(const SurfaceMesh& surface, const View& view) {
  if (surface.triangles.empty()) return false;
  double length = 0;
  const std::size_t step = std::max<std::size_t>(1, surface.triangles.size() / 1000);
  std::size_t measured = 0;
  for (std::size_t f = 0; f < surface.triangles.size(); f += step, ++measured) {
    const Triangle& t = surface.triangles[f];
    const Point a = view.to_screen(surface.vertices[t[0]]), b = view.to_screen(surface.vertices[t[1]]);
    length += (a - b).head<2>().norm();
  }
  return length / static_cast<double>(measured) >= 6;
}

void draw_surface(Picture& picture, const View& view, const SurfaceMesh& surface, bool by_region) {
  const bool edges = by_region && edges_show(surface, view);
  for (std::size_t f = 0; f < surface.triangles.size(); ++f) {
    const Triangle& t = surface.triangles[f];
    const std::vector<Point> corners = {surface.vertices[t[0]], surface.vertices[t[1]], surface.vertices[t[2]]};
    const Point normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
    const Rgb colour = by_region ? report::region_colour(seen_region(surface, f, normal, view)) : Rgb{236, 236, 236};
    draw_polygon(picture, view, corners, colour, edges);
  }
}

Picture surface_picture(const SurfaceMesh& surface) {
  Picture picture(kPictureWidth, kPictureHeight, kBackground);
  const Box box = bounds(surface.vertices);
  if (box.isEmpty()) return picture;
  draw_surface(picture, three_quarter_view(box, kPictureWidth, kPictureHeight), surface, true);
  return picture;
}

std::vector<Point> face_corners(const VoronoiMesh& mesh, const VoronoiFace& face) {
  std::vector<Point> corners;
  corners.reserve(face.points.size());
  for (Index p : face.points) corners.push_back(mesh.points[p]);
  return corners;
}

// A plane across the mesh's thinnest extent through its middle, so that the cut shows the most
// cells: the cells with a point on its far side are drawn whole.
struct Cut {
  int axis = 0;
  double at = 0;
  std::vector<char> kept;   // per cell
  std::size_t crossed = 0;  // cells with points on both sides
};

Cut cut_across(const VoronoiMesh& mesh, const Box& box) {
  Cut cut;
  box.sizes().minCoeff(&cut.axis);
  cut.at = box.center()[cut.axis];
  cut.kept.assign(mesh.cells.size(), 0);
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (Index f : mesh.cells[c].faces) {
      for (Index p : mesh.faces[f].points) {
        low = std::min(low, mesh.points[p][cut.axis]);
        high = std::max(high, mesh.points[p][cut.axis]);
      }
    }
    cut.kept[c] = high >= cut.at;
    if (low < cut.at && high > cut.at) ++cut.crossed;
  }
  return cut;
}

Picture cut_picture(const VoronoiMesh& mesh, int width, int height, std::string* caption) {
  Picture picture(width, height, kBackground);
  const Box box = bounds(mesh.points);
  if (box.isEmpty()) return picture;
  const Cut cut = cut_across(mesh, box);
  // Looking at the plane from its near side, a little askew so that the cut cells' sides show.
  const int a = cut.axis, b = (a + 1) % 3, c = (a + 2) % 3;
  Point forward = Point::Zero(), up = Point::Zero();
  forward[a] = 1;
  forward[b] = 0.25;
  forward[c] = 0.18;
  up[a == 2 ? 1 : 2] = 1;
  const View view(box.min(), box.max(), forward, up, width, height);
  const auto kept = [&](std::int32_t cell) { return cell != kNoCell && cut.kept[static_cast<std::size_t>(cell)]; };
  for (const VoronoiFace& face : mesh.faces) {
    // Only the hull of the kept cells shows.
    if (kept(face.owner) == kept(face.neighbour)) continue;
    const VoronoiCell& cell = mesh.cells[static_cast<std::size_t>(kept(face.owner) ? face.owner : face.neighbour)];
    draw_polygon(picture, view, face_corners(mesh, face), report::region_colour(cell.region), true);
  }
  if (caption) {
    *caption = count(cut.crossed) + " cells cut by the plane " + std::string(1, "xyz"[a]) + " = " + figure(cut.at) +
               ", coloured by material; the cells beyond it are drawn whole";
  }
  return picture;
}

// The cells of the largest aspect ratio, worst first (ties by cell order).
std::vector<std::size_t> worst_cells(const CellQuality& quality) {
  std::vector<std::size_t> order(quality.cells.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const std::size_t n = std::min(kWorstCells, order.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(n), order.end(),
                    [&](std::size_t i, std::size_t j) {
                      const double ri = quality.cells[i].aspect_ratio, rj = quality.cells[j].aspect_ratio;
                      return ri > rj || (ri == rj && i < j);
                    });
  order.resize(n);
  return order;
}

Picture worst_cells_picture(const MeshResult& result, const std::vector<std::size_t>& worst) {
  Picture picture(kPictureWidth, kPictureHeight, kBackground);
  Box box = bounds(result.surface.vertices);
  for (const Point& p : result.cells.points) box.extend(p);
  if (box.isEmpty()) return picture;
  const View view = three_quarter_view(box, kPictureWidth, kPictureHeight);
  draw_surface(picture, view, result.surface, false);
  // In front of the surface, wherever they are.
  picture.clear_depth();
  for (std::size_t c : worst) {
    for (Index f : result.cells.cells[c].faces) {
      draw_polygon(picture, view, face_corners(result.cells, result.cells.faces[f]), Rgb{214, 39, 40}, true);
    }
  }
  return picture;
}

std::string png_uri(const Picture& picture) {
  return "data:image/png;base64," + report::base64(report::encode_png(picture));
}

void image(std::ostream& html, const std::string& id, const std::string& uri, const std::string& caption) {
  html << "<figure><img id=\"" << id << "\" src=\"" << uri << "\" alt=\"" << text(caption) << "\">\n<figcaption>"
       << text(caption) << "</figcaption></figure>\n";
}

using Row = std::vector<std::string>;  // cells already escaped

// The first column names the row; the others are figures, set right.
void table(std::ostream& html, const std::string& id, const Row& header, const std::vector<Row>& rows) {
  html << "<table id=\"" << id << "\">\n<tr>";
  for (const std::string& h : header) html << "<th>" << h << "</th>";
  html << "</tr>\n";
  for (const Row& row : rows) {
    html << "<tr>";
    for (std::size_t i = 0; i < row.size(); ++i) html << (i == 0 ? "<td>" : "<td class=\"n\">") << row[i] << "</td>";
    html << "</tr>\n";
  }
  html << "</table>\n";
}

std::string optional_figure(const std::optional<double>& x) { return x ? figure(*x) : "&mdash;"; }

void regions_table(std::ostream& html, const MeshResult& result) {
  const std::size_t labels = result.regions.size();
  std::vector<std::size_t> cells(labels, 0);
  std::vector<double> volume(labels, 0);
  for (const VoronoiCell& cell : result.cells.cells) {
    if (cell.region < 0 || static_cast<std::size_t>(cell.region) >= labels) continue;
    ++cells[static_cast<std::size_t>(cell.region)];
    volume[static_cast<std::size_t>(cell.region)] += cell.volume;
  }
  const bool have_cells = !result.cells.cells.empty();
  std::vector<Row> rows;
  for (std::size_t label = 0; label < labels; ++label) {
    const RegionSummary& region = result.regions[label];
    const RegionVolume* enclosed = nullptr;
    for (const RegionVolume& v : result.surface_quality->region_volumes) {
      if (v.name == region.name) enclosed = &v;
    }
    rows.push_back({text(region.name), count(label), count(region.pieces),
                    have_cells && label > 0 ? count(cells[label]) : "&mdash;",
                    have_cells && label > 0 ? figure(volume[label]) : "&mdash;",
                    enclosed ? optional_figure(enclosed->input) : "&mdash;",
                    enclosed ? optional_figure(enclosed->output) : "&mdash;"});
  }
  table(html, "regions",
        {"region", "label", "pieces", "cells", "cells' volume", "enclosed by the input", "enclosed by the output"}, rows);
}

void surface_table(std::ostream& html, const SurfaceQuality& q) {
  const auto topology = [](const SurfaceTopology& t) {
    return count(t.components) + " components, " + count(t.boundary_edges) + " boundary and " +
           count(t.non_manifold_edges) + " non-manifold edges";
  };
  table(html, "surface-quality", {"measure", "value"},
        {{"triangles", count(q.triangles)},
         {"smallest angle (degrees)", figure(q.min_angle_degrees)},
         {"largest angle (degrees)", figure(q.max_angle_degrees)},
         {"angles below 30 degrees (%)", figure(q.percent_angles_below_30)},
         {"angles above 90 degrees (%)", figure(q.percent_angles_above_90)},
         {"triangle quality, smallest", figure(q.min_quality)},
         {"triangle quality, mean", figure(q.mean_quality)},
         {"Hausdorff distance to the input", figure(q.hausdorff)},
         {"the same, of the bounding box's diagonal (%)", figure(100 * q.hausdorff_relative)},
         {"volume enclosed by the input", optional_figure(q.input_volume)},
         {"volume enclosed by the output", optional_figure(q.output_volume)},
         {"its change (%)", optional_figure(q.volume_change_percent())},
         {"topology of the input", topology(q.input_topology)},
         {"topology of the output", topology(q.output_topology)},
         {"same topology", q.topology_matches ? "yes" : "no"}});
}

void cells_tables(std::ostream& html, const MeshResult& result, const std::vector<std::size_t>& worst) {
  const CellQuality& q = *result.cell_quality;
  table(html, "cell-quality", {"measure", "smallest", "mean", "largest"},
        {{"aspect ratio R / r", figure(q.min_aspect_ratio), figure(q.mean_aspect_ratio), figure(q.max_aspect_ratio)},
         {"volume", figure(q.min_volume), figure(q.total_volume / static_cast<double>(q.cells.size())),
          figure(q.max_volume)},
         {"faces", count(q.min_faces), figure(q.mean_faces), count(q.max_faces)},
         {"shortest edge over the cube root of the volume", figure(q.min_shortest_edge_relative),
          figure(q.mean_shortest_edge_relative), "&mdash;"}});
  std::vector<Row> parts;
  for (const LayerParts* layer : q.layers()) {
    if (layer->cells == 0) continue;
    const auto row = [&](const std::string& measure, const PartDistribution& d, std::size_t threshold) {
      parts.push_back({text(layer->name), count(layer->cells), text(measure), figure(d.min), figure(d.mean),
                       figure(d.max), figure(d.thresholds[threshold]), figure(d.percent_below(threshold))});
    };
    row("edge length / cell size", layer->edge_length, 0);
    row("face area / cell size squared", layer->face_area, 0);
    row("dihedral angle (degrees)", layer->dihedral_angle, 0);
  }
  table(html, "cell-parts", {"layer", "cells", "measure", "smallest", "mean", "largest", "threshold", "below it (%)"},
        parts);
  html << "<p>" << count(q.cells.size()) << " cells, of total volume " << figure(q.total_volume) << "; "
       << count(q.aspect_ratio_above_high) << " with an aspect ratio above " << figure(q.histogram_high) << ".</p>\n";
  std::vector<Row> rows;
  for (std::size_t rank = 0; rank < worst.size(); ++rank) {
    const std::size_t c = worst[rank];
    const CellShape& shape = q.cells[c];
    const VoronoiCell& cell = result.cells.cells[c];
    rows.push_back({count(rank + 1), count(c), count(cell.seed), text(region_name(result.cells, cell.region)),
                    figure(shape.aspect_ratio), figure(shape.volume), count(shape.faces),
                    figure(shape.shortest_edge_relative)});
  }
  table(html, "worst-cells",
        {"rank", "cell", "seed", "material", "aspect ratio", "volume", "faces", "shortest edge (relative)"}, rows);
}

constexpr const char* kStyle =
    "body{font-family:sans-serif;max-width:1000px;margin:2em auto;padding:0 1em;color:#222}"
    "h1{font-size:1.6em}h2{font-size:1.25em;margin-top:1.8em;border-bottom:1px solid #ccc}"
    "table{border-collapse:collapse;margin:.6em 0 1.2em}th,td{border:1px solid #ccc;padding:3px 9px;text-align:left}"
    "th{background:#f2f2f2}td.n{text-align:right;font-variant-numeric:tabular-nums}"
    "figure{margin:1em 0}img{max-width:100%;border:1px solid #ddd}figcaption{color:#555;font-size:.9em}"
    ".warnings li{color:#8a4b00}";

}  // namespace

std::string cut_picture_png(const MeshResult& result, int width, int height) {
  if (result.cells.cells.empty()) throw Error(Error::Kind::Usage, "the run has no cells to cut");
  if (width < 16 || height < 16 || width > 8192 || height > 8192) {
    throw Error(Error::Kind::Usage, "a picture must be 16 to 8192 pixels wide and high");
  }
  return report::encode_png(cut_picture(result.cells, width, height, nullptr));
}

std::string report_html(const MeshResult& result, const ReportPage& page) {
  if (!result.surface_quality) {
    throw Error(Error::Kind::Usage, "report.html needs a run that reached the surface (stop_after surface or later)");
  }
  const bool have_cells = !result.cells.cells.empty() && result.cell_quality;
  std::ostringstream html;
  html.imbue(std::locale::classic());
  html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>VoroCrust: " << text(page.title)
       << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n<h1>VoroCrust mesh of " << text(page.title)
       << "</h1>\n";

  html << "<h2>The run</h2>\n";
  std::vector<Row> summary;
  for (const std::string& line : page.summary) summary.push_back({text(line)});
  table(html, "summary", {"summary"}, summary);
  if (!page.warnings.empty()) {
    html << "<ul class=\"warnings\">\n";
    for (const std::string& w : page.warnings) html << "<li>" << text(w) << "</li>\n";
    html << "</ul>\n";
  }

  html << "<h2>Pictures</h2>\n";
  image(html, "surface-picture", png_uri(surface_picture(result.surface)),
        "The output surface, " + count(result.surface.triangles.size()) + " triangles, coloured by region");
  std::vector<std::size_t> worst;
  if (have_cells) {
    std::string caption;
    const Picture cut = cut_picture(result.cells, kPictureWidth, kPictureHeight, &caption);
    image(html, "cut-picture", png_uri(cut), caption);
    worst = worst_cells(*result.cell_quality);
    image(html, "worst-cells-picture", png_uri(worst_cells_picture(result, worst)),
          "The " + count(worst.size()) + " cells of the largest aspect ratio, in red over the surface");
  } else {
    html << "<p>The run stopped before the cells.</p>\n";
  }

  html << "<h2>Regions</h2>\n";
  regions_table(html, result);
  html << "<h2>Surface quality</h2>\n";
  surface_table(html, *result.surface_quality);
  if (have_cells) {
    html << "<h2>Cell quality</h2>\n";
    cells_tables(html, result, worst);
  }

  html << "<h2>Histograms</h2>\n";
  const std::string svg = histogram_svg("quality: " + page.title, quality_panels(result.surface_quality, result.cell_quality));
  image(html, "histograms", "data:image/svg+xml;base64," + report::base64(svg),
        "Triangle quality of the surface" + std::string(have_cells ? " and aspect ratio of the cells" : ""));

  html << "<h2>Timings</h2>\n";
  std::vector<Row> timings;
  double total = 0;
  std::size_t peak = 0;
  const auto megabytes = [](std::size_t bytes) {
    return report::locale_free_number(static_cast<double>(bytes) / 1e6, std::chars_format::fixed, 1);
  };
  for (const PhaseTiming& t : page.timings) {
    timings.push_back(
        {text(t.name), report::locale_free_number(t.seconds, std::chars_format::fixed, 3), megabytes(t.peak_resident_bytes)});
    total += t.seconds;
    peak = std::max(peak, t.peak_resident_bytes);
  }
  timings.push_back({"all", report::locale_free_number(total, std::chars_format::fixed, 3), megabytes(peak)});
  table(html, "timings", {"phase", "seconds", "peak resident MB by its end"}, timings);
  html << "</body>\n</html>\n";
  return html.str();
}

void write_report_html(const std::filesystem::path& path, const MeshResult& result, const ReportPage& page) {
  write_file_atomically(path, report_html(result, page));
}

}  // namespace vorocrust
