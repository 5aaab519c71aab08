// vorocrust/cells.hpp — the conforming Voronoi mesh of a labelled seed set.
//
// compute_cells(seeds, options) gives the Voronoi cell of every seed whose region is a material,
// assembled into one conforming polyhedral mesh:
// - a Voronoi vertex shared by several cells is one point. Near-degenerate vertices (five or more
//   seeds nearly on one sphere, the rule at VoroCrust's surface seeds) are welded: points closer
//   than 1e-9 of their empty-sphere radius (and never less than 1e-9 of the seeds' mean spacing)
//   are one point, for every cell that has them; edges and faces this collapses are dropped on
//   both sides alike. Where two cells disagree on their common face, the points that only split
//   an edge of every cell that has them are dropped (four seeds on one circle leave such points
//   on one side of a face); where they still disagree, they and their neighbours are cut again,
//   each checked to hold nothing nearer another seed, and the tolerance rises for the whole set,
//   by tens up to 1e-6;
// - every face is listed once, in the order of its owner cell. Its polygon's normal (right-hand
//   rule) points from its owner cell to the other side; between two material cells the owner is
//   the lower cell index. Points are numbered in the order the faces first use them;
// - every cell is closed (each edge of the cell used by exactly two of its faces, once in each
//   direction) and convex.
// Cells are numbered in seed order; every point sits at equal distance from the seeds of the
// cells around it (the seeds it is the circumcentre of), so faces are orthogonal to the links
// between the seeds they separate.
//
// Throws Error(InvalidGeometry) when no seed is a material, when a seed is not finite, when a
// material seed coincides with another seed, and "cell of seed N is not bounded by seeds" when a
// material cell reaches past every other seed (the seeds do not enclose the materials: outside
// seeds must surround them). The result does not depend on options.threads.
#pragma once

#include "vorocrust/api.hpp"

#include <cstdint>
#include <string>
#include <vector>

#include "vorocrust/seeds.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

inline constexpr std::int32_t kNoCell = -1;

struct VOROCRUST_API CellsOptions {
  std::vector<std::int32_t> materials;  // regions that get cells; empty: every region > 0
  int threads = 0;                      // 0 = all hardware threads
};

struct VOROCRUST_API VoronoiFace {
  std::vector<Index> points;  // the polygon; its normal points from owner to neighbour side
  std::int32_t owner = kNoCell;
  std::int32_t neighbour = kNoCell;  // kNoCell when the other side is no material cell
  Index owner_seed = 0;
  Index neighbour_seed = 0;  // the seed across the face, a cell's or not
  RegionPair regions;        // back: the owner's region; front: the region across the face
};

struct VOROCRUST_API VoronoiCell {
  Index seed = 0;
  Point site = Point::Zero();  // the seed's position: the node simulators put the cell's values at
  SeedKind seed_kind = SeedKind::Interior;  // the seed's (surface and cap seeds lie on protecting spheres)
  std::int32_t region = 0;
  std::vector<Index> faces;  // into VoronoiMesh::faces
  double volume = 0;
  Point centroid = Point::Zero();
};

struct VOROCRUST_API VoronoiMesh {
  std::vector<Point> points;
  std::vector<VoronoiFace> faces;
  std::vector<VoronoiCell> cells;
  // The regions' names by label, as the input named them (vorocrust/regions.hpp); empty when the
  // seeds came without names, and the writers then say "outside" (0) and "material<N>".
  std::vector<std::string> region_names;
  // A 2D mesh extruded one cell thick (plane.hpp): the region across its front and back faces,
  // an `empty` patch in OpenFOAM's case; kNoCell for a 3D mesh.
  std::int32_t empty_region = kNoCell;
};

VOROCRUST_API VoronoiMesh compute_cells(const std::vector<Seed>& seeds, const CellsOptions& options = {});

// A face's area, its unit normal (from owner to the other side) and its centroid, from the
// triangles fanned about its vertex mean, as the cells' volumes are measured.
struct VOROCRUST_API FaceGeometry {
  double area = 0;
  Point normal = Point::Zero();
  Point centroid = Point::Zero();
};
VOROCRUST_API FaceGeometry face_geometry(const VoronoiMesh& mesh, std::size_t face);

// The name of region `label`: mesh.region_names[label] where given, else "outside" for 0 and
// "material<N>" for N.
VOROCRUST_API std::string region_name(const VoronoiMesh& mesh, std::int32_t label);

// The figures every summary of a mesh gives: faces with a cell on both sides, those among them
// whose two cells are of different materials (the interfaces), and the sum of the cells' volumes.
VOROCRUST_API std::size_t count_interior_faces(const VoronoiMesh& mesh);
VOROCRUST_API std::size_t count_interface_faces(const VoronoiMesh& mesh);
VOROCRUST_API double total_volume(const VoronoiMesh& mesh);

}  // namespace vorocrust
