// What a run says about itself, a line each: the same lines on the CLI's terminal, in MeshLab's
// log, in FreeCAD's report view and in Python's MeshResult.summary.
#include <algorithm>

#include "core/c_format.hpp"
#include "vorocrust/face_skewness.hpp"
#include "vorocrust/report.hpp"

namespace vorocrust {

namespace {

std::size_t count_kind(const std::vector<Seed>& seeds, SeedKind kind) {
  return static_cast<std::size_t>(std::count_if(seeds.begin(), seeds.end(), [&](const Seed& s) { return s.kind == kind; }));
}

}  // namespace

std::vector<std::string> run_warnings(const MeshResult& result) {
  std::vector<std::string> lines;
  const SelfIntersectionStats& s = result.self_intersections;
  if (s.faces_cut > 0) {
    lines.push_back(c_format("self-intersections resolved: %zu faces cut along their intersection curves (%zu new "
                            "points), %zu faces left inside one region dropped, %zu faces in all",
                            s.faces_cut, s.points_added, s.faces_dropped, s.faces));
  }
  const FeatureCounts& f = result.features;
  if (f.smoothing_rounds_refused > 0 || f.smoothing_rounds_crossing > 0) {
    std::string why;
    if (f.smoothing_rounds_refused > 0) {
      why += "; " + std::to_string(f.smoothing_rounds_refused) + " would make a sharp feature the input lacks";
    }
    if (f.smoothing_rounds_crossing > 0) {
      why += "; " + std::to_string(f.smoothing_rounds_crossing) + " would carry the surface through itself";
    }
    lines.push_back(c_format("smoothing kept %d round(s)%s", f.smoothing_iterations, why.c_str()));
  }
  return lines;
}

std::string face_figures_line(const CellQuality& q) {
  return c_format("faces orthogonal to their seed links within %.2g deg (face %zu); against the cell centroids, as "
                 "checkMesh measures: non-orthogonality max %.3g deg, mean %.3g deg, skewness max %.3g, %zu faces "
                 "above %g",
                 q.max_link_angle, q.link_angle_face, q.max_non_orthogonality, q.mean_non_orthogonality,
                 q.max_skewness, q.highly_skew_faces, kHighSkewness);
}

std::vector<std::string> run_summary(const MeshResult& result, const MeshOptions& options) {
  std::vector<std::string> lines;
  const RefinementStats& r = result.refinement;
  const FeatureCounts& f = result.features;
  lines.push_back(c_format("%zu balls (%zu corner, %zu crease, %zu patch) protecting %zu corners, %zu creases and "
                          "%zu patches",
                          r.balls[0] + r.balls[1] + r.balls[2], r.balls[0], r.balls[1], r.balls[2], f.corners,
                          f.creases, f.patches));
  if (options.stop_after < Stage::Surface) return lines;
  const std::size_t splits = result.slivers.rounds_for(SliverIteration::Shrunk::ForSkinnyTriangles);
  lines.push_back(c_format("%zu surface seeds, a surface of %zu triangles after %zu rounds of sliver elimination%s",
                          count_kind(result.seeds, SeedKind::Surface), result.surface.num_faces(),
                          result.slivers.rounds_for(SliverIteration::Shrunk::ForSlivers),
                          splits > 0 ? (" and " + std::to_string(splits) + " of splitting skinny triangles").c_str() : ""));
  const SurfaceQuality& q = *result.surface_quality;
  lines.push_back(c_format("smallest angle %.1f deg, %.2f %% of angles below 30 deg, Q min %.3f, mean %.3f, Hausdorff "
                          "%.3f %% of the diagonal, topology %s",
                          q.min_angle_degrees, q.percent_angles_below_30, q.min_quality, q.mean_quality,
                          100 * q.hausdorff_relative, q.topology_matches ? "as the input's" : "DIFFERS from the input's"));
  if (options.stop_after < Stage::Cells) return lines;
  const InteriorStats& i = result.interior;
  lines.push_back(c_format("%zu interior and %zu outside seeds (%s); %zu cells, %zu faces (%zu between cells), volume "
                          "%.10g",
                          i.interior_seeds, i.outside_seeds, to_string(options.interior), result.cells.cells.size(),
                          result.cells.faces.size(), count_interior_faces(result.cells), total_volume(result.cells)));
  const CellQuality& c = *result.cell_quality;
  lines.push_back(c_format("cell aspect ratio %.3g mean, %.3g max (seed %u); %zu cells above %.3g", c.mean_aspect_ratio,
                          c.max_aspect_ratio, c.worst_seed, c.aspect_ratio_above_high, c.histogram_high));
  lines.push_back(face_figures_line(c));
  return lines;
}

std::vector<std::string> written_lines(const std::filesystem::path& folder, const std::vector<OutputFormat>& formats) {
  std::vector<std::string> lines;
  for (OutputFormat format : formats) {
    const std::string where = (folder / std::string(output_format(format).files[0])).string();
    switch (format) {
      case OutputFormat::Vtu: lines.push_back("wrote " + where + " (open it in ParaView)"); break;
      case OutputFormat::OpenFoam: lines.push_back("wrote " + where + "/ (check it with: checkMesh -case " + where + ")"); break;
      case OutputFormat::Tough: lines.push_back("wrote " + where + " (TOUGH's ELEME and CONNE blocks)"); break;
      case OutputFormat::Pflotran:
        lines.push_back("wrote " + where + "/ (mesh.uge for GRID TYPE UNSTRUCTURED_EXPLICIT, a region file per material "
                        "and per boundary patch)");
        break;
      case OutputFormat::Exodus: lines.push_back("wrote " + where + " (Exodus II: a block per material; ParaView reads it)"); break;
      default: break;
    }
  }
  return lines;
}

}  // namespace vorocrust
