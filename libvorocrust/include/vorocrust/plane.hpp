// vorocrust/plane.hpp — conforming Voronoi meshes of 2D domains (paper 2.6, Figure 10).
//
// A 2D domain is a planar straight-line graph (PSLG): points, segments between them, hole points
// and region points, as Triangle's .poly files give them. mesh_plane protects every segment as
// VoroCrust protects creases in 3D: circles centred on the segments, consecutive circles
// overlapping, a circle at every corner; a pair of seeds where consecutive circles meet, one on
// each side; interior seeds outside the circles; and takes the Voronoi cells as they are.
//
// Contract of mesh_plane(domain, options):
// - The domain is prepared first (prepare_planar_domain): errors name the file and line.
// - Every Voronoi vertex at a circle's centre is shared by the cells of the seeds on that circle,
//   so the cells' edges between the seeds of a pair run exactly from one circle's centre to the
//   next: each input segment is followed by a chain of cell edges whose vertices lie on it (at
//   sharp corners and segment ends exactly; along a polyline whose vertices are not corners,
//   within the sagitta of the chord between consecutive centres, which PlaneStats reports).
// - Regions are the parts of the plane the segments enclose, found from the cells: cells joined
//   by an edge that is not a seed pair's belong to one region. A region holding a hole point,
//   or reaching the frame around the domain, is not meshed. Region points give labels; regions
//   without one are labelled after them (`inside` when there is one region and no label).
//   Segments inside a region whose ends are free (breaklines, faults that end inside a layer)
//   are followed by cell edges like the others; both sides keep the region's label.
// - Cells are convex polygons, counter-clockwise, with at every edge the cell across (or kNoCell
//   where the other side is not meshed) and the region across. Every edge between two meshed
//   cells is orthogonal to the link between their seeds and lies on its bisector.
// - The same domain, options and seed give the same mesh, whatever the number of threads.
// Throws Error(InvalidGeometry) naming the place for a domain that cannot be meshed (open
// boundaries, region points in no closed region, features closer than the circles can resolve)
// and Error(Usage) for options out of range.
#pragma once

#include "vorocrust/api.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "vorocrust/cells.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/modes.hpp"
#include "vorocrust/options.hpp"
#include "vorocrust/seeds.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

using Point2 = Eigen::Vector2d;

// A point inside a region, with the label its cells get (Triangle's regional attribute).
struct VOROCRUST_API RegionPoint {
  Point2 at = Point2::Zero();
  std::int32_t label = kInsideRegion;
  std::size_t line = 0;  // in PlanarDomain::file, 0 where none
};

struct VOROCRUST_API PlanarDomain {
  std::vector<Point2> points;
  std::vector<std::array<Index, 2>> segments;
  std::vector<std::size_t> segment_lines;  // each segment's line in `file`; empty, or 0 where none
  std::vector<Point2> holes;
  std::vector<RegionPoint> regions;
  std::vector<std::string> region_names;  // by label, where the input names them
  std::string file;                       // for messages; empty for arrays
};

// Reads a 2D domain: Triangle's .poly (vertices, segments, holes, regional attributes; vertices
// numbered from 0 or 1 as the file's first one is), or OBJ polylines (`v x y z` with one z for
// all, `l a b c ...`). Throws Error(UnreadableInput) naming the file and line.
VOROCRUST_API PlanarDomain read_planar_domain(const std::filesystem::path& path);

// The domain as mesh_plane meshes it: points given twice merged, segments that cross split at
// their crossing (decided by exact orientation tests) and segments through a point split there.
// Throws Error(InvalidGeometry) naming the segment (and its line) for a segment of zero length,
// a segment given twice, segments that overlap along a stretch, a point or number not finite, or
// a domain without segments.
VOROCRUST_API PlanarDomain prepare_planar_domain(const PlanarDomain& domain);

// A point as messages give it, "(0.1, -2)", to 9 significant digits.
VOROCRUST_API std::string describe_point(const Point2& p);

struct VOROCRUST_API PlaneOptions {
  double lipschitz = 0.25;                                    // how fast circle radii may vary
  double max_size = std::numeric_limits<double>::infinity();  // bound on circle radii and spacing
  std::filesystem::path sizing_file;                          // "x y size" or "x y z size" lines
  double sharp_angle_degrees = 30;  // a polyline turning more than this at a point has a corner
  InteriorMode interior = InteriorMode::Random;
  int cvt_iterations = 20;
  std::uint64_t seed = 0;
  int threads = 0;
  void check() const;  // Error(Usage) naming the option out of range
};

// The options of the library's one table (options.hpp) that a 2D run takes, by name, and
// their values in force in `options` as PlaneOptions: every front end offers these, spelled as
// it spells the table's.
VOROCRUST_API std::vector<std::string_view> plane_option_names();
VOROCRUST_API PlaneOptions plane_options(const MeshOptions& options);

struct VOROCRUST_API PlaneCircle {
  Point2 centre = Point2::Zero();
  double radius = 0;
  bool corner = false;  // centred on a corner or a segment's free end
};

struct VOROCRUST_API PlaneCell {
  Index seed = 0;
  std::int32_t region = 0;
  std::vector<Index> points;            // counter-clockwise
  std::vector<std::int32_t> across;     // per edge points[i] -> points[i+1]: the cell there, or kNoCell
  std::vector<std::int32_t> regions_across;  // the region there (0: not meshed)
  std::vector<std::int64_t> seeds_across;    // the seed there, or -1 - side at the frame
  double area = 0;
  Point2 centroid = Point2::Zero();
};

struct VOROCRUST_API PlaneStats {
  std::size_t corners = 0, chains = 0, circles = 0, refinement_rounds = 0;
  std::size_t pair_seeds = 0, cap_seeds = 0, interior_seeds = 0, outside_seeds = 0;
  std::size_t crossings_split = 0;
  double largest_sagitta = 0;  // farthest an input point lies from the chords between centres
  std::vector<std::pair<std::string, double>> seconds;  // per phase
};

struct VOROCRUST_API PlaneMesh {
  std::vector<Point2> points;
  std::vector<PlaneCell> cells;  // the meshed ones, in seed order
  std::vector<Seed> seeds;       // every seed, meshed or not, z = 0
  std::vector<PlaneCircle> circles;
  std::vector<std::string> region_names;  // by label; "outside" at 0
  PlanarDomain domain;                    // as meshed: prepare_planar_domain's
  PlaneStats stats;
};

VOROCRUST_API PlaneMesh mesh_plane(const PlanarDomain& domain, const PlaneOptions& options = {});

// The mesh extruded `thickness` along z, one cell thick: each cell a prism, the Voronoi cell in
// 3D of its seed lifted to mid-thickness within the slab. The front and back faces lie across
// the region named "frontAndBack" (VoronoiMesh::empty_region), which OpenFOAM's case makes an
// `empty` patch. For the 3D writers: OpenFOAM, TOUGH, PFLOTRAN, Exodus.
VOROCRUST_API VoronoiMesh extrude_plane_mesh(const PlaneMesh& mesh, double thickness);

// mesh.vtu: VTK polygons at z = 0, cell data material, seed, area, aspect_ratio; the aspect
// ratios from `quality` when given (measure_plane_quality's of this mesh), else measured here.
struct PlaneQuality;
VOROCRUST_API void write_plane_vtu(const PlaneMesh& mesh, const std::filesystem::path& path,
                                   const PlaneQuality* quality = nullptr);
// mesh.svg: the cells coloured by material, the seeds, the segments of mesh.domain over them.
VOROCRUST_API void write_plane_svg(const PlaneMesh& mesh, const std::filesystem::path& path);

// Figures of a 2D mesh, as report.json gives them.
struct VOROCRUST_API PlaneQuality {
  std::size_t cells = 0, edges = 0, boundary_edges = 0, interface_edges = 0;
  double min_angle = 0, max_angle = 0;               // interior angles of the cells, degrees
  double max_aspect_ratio = 0, mean_aspect_ratio = 0;  // enclosing over inscribed circle radius
  double min_shortest_edge = 0;  // shortest edge over the square root of its cell's area
  std::size_t edges_below_0_01 = 0, edges_below_0_1 = 0;
  double max_link_angle = 0;  // degrees by which an edge between two cells departs from orthogonal to their seeds' link
  bool convex = true;
  std::vector<double> area_by_region;  // by label
  std::vector<double> aspect_ratio;    // per cell
};
VOROCRUST_API PlaneQuality measure_plane_quality(const PlaneMesh& mesh);

// A whole 2D run as the CLI's `mesh2d` and the Python module run it: read (or take) the domain,
// mesh it, write the formats asked for into the output folder, and report.json there, always
// (with the error, when the run fails, and the error rethrown).
// Formats: vtu (mesh.vtu, polygons), svg (mesh.svg), openfoam (case/, one cell thick, front and
// back an `empty` patch), tough (MESH), pflotran (pflotran/), exodus (mesh.exo), seeds
// (seeds.csv); the last four from the slab `thickness` thick.
struct VOROCRUST_API PlaneJob {
  std::filesystem::path input;          // read when `domain` is not given
  std::optional<PlanarDomain> domain;   // a domain in memory
  PlaneOptions options;
  double thickness = 1;
  std::vector<std::string> formats;     // empty: all
  std::filesystem::path output_dir;     // empty: nothing written
  std::vector<std::string> command;     // for report.json
};

struct VOROCRUST_API PlaneJobResult {
  PlaneMesh mesh;
  PlaneQuality quality;
  std::vector<std::string> summary;  // lines for a person
};

VOROCRUST_API std::vector<std::string> plane_format_names();
VOROCRUST_API PlaneJobResult run_plane_job(const PlaneJob& job);

}  // namespace vorocrust
