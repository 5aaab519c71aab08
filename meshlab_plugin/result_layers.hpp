// Turning what vorocrust::generate_mesh returns into MeshLab layers.
#pragma once

#include <vector>

#include "vorocrust/balls.hpp"
#include "vorocrust/mesher.hpp"

class MeshDocument;
class MeshModel;

namespace vorocrust::meshlab {

// Per-vertex and per-face float attributes of the layers. Floats, because MeshLab's PLY export
// and its attribute tools handle float attributes; numbers are exact up to 2^24.
inline constexpr const char* kRadiusAttribute = "radius";
inline constexpr const char* kStratumTypeAttribute = "stratum_type";    // 0 corner, 1 crease, 2 patch
inline constexpr const char* kStratumIndexAttribute = "stratum_index";  // corner, crease or patch number
// The surface's faces: the regions behind and in front of a face, as the PLY properties of
// vorocrust's surface.ply name them (-1 where unknown).
inline constexpr const char* kBackRegionAttribute = "back_region";
inline constexpr const char* kFrontRegionAttribute = "front_region";
// The seeds: the region (material) a seed belongs to, 0 outside, and its kind (0 surface,
// 1 interior, 2 outside, 3 cap), as seeds.csv's `label` and `kind` columns.
inline constexpr const char* kLabelAttribute = "label";
inline constexpr const char* kSeedKindAttribute = "kind";

// The layers one run added to the document; null where a run to its stage makes none.
struct ResultLayers {
  MeshModel* balls = nullptr;
  MeshModel* surface = nullptr;
  MeshModel* seeds = nullptr;
};

// Every layer is named "SOURCE VoroCrust WHAT" (SOURCE: the source layer's label without its
// extension and with no dot, so "bunny.off" gives "bunny VoroCrust balls"), carries the source
// layer's transformation matrix and has its bounding box set.

// Adds the point layer "SOURCE VoroCrust balls" and makes it current: one vertex per ball centre,
// in the library's order (balls.csv's rows), with the radius as the float attribute "radius" and
// as vertex quality (so Colorize by vertex quality and the quality histogram work), the stratum
// as "stratum_type" and "stratum_index", and a colour per stratum type (corners red, creases
// yellow, patches grey-blue).
MeshModel* add_balls_layer(MeshDocument& md, const std::vector<Ball>& balls, const MeshModel& source);

// Adds the triangle layer "SOURCE VoroCrust surface": the vertices and faces of `surface` in its
// order (surface.ply's), each face with its region pair as "back_region" and "front_region", its
// triangle quality Q (vorocrust/quality.hpp) as face quality, so MeshLab's Colorize by face
// quality and its quality histogram show it, and a colour per region pair: the pairs present,
// in increasing (back, front) order, take the colours of one fixed palette in turn.
MeshModel* add_surface_layer(MeshDocument& md, const SurfaceMesh& surface, const MeshModel& source);

// Adds the point layer "SOURCE VoroCrust seeds": one vertex per seed in the library's order
// (seeds.csv's rows), with its region as "label", its kind as "kind", its radius as "radius" and
// as vertex quality, and a colour per label: outside (0) grey, material N the palette's colour N
// (cycling), so the two seeds of a surface pair show on which side each lies.
MeshModel* add_seeds_layer(MeshDocument& md, const std::vector<Seed>& seeds, const MeshModel& source);

// Adds every layer a run up to `stage` yields: the balls for Stage::Balls; the surface and the
// seeds from Stage::Surface on, the surface made current. On failure the layers added so far are
// removed again and the exception goes on.
ResultLayers add_result_layers(MeshDocument& md, const MeshResult& result, Stage stage, const MeshModel& source);

}  // namespace vorocrust::meshlab
