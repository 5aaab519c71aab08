// Turning what vorocrust::generate_mesh returns into MeshLab layers.
#pragma once

#include <vector>

#include "vorocrust/balls.hpp"
#include "vorocrust/mesher.hpp"

class MeshDocument;
class MeshModel;

namespace vorocrust::meshlab {

// Per-vertex float attributes of the balls layer. Floats, because MeshLab's PLY export and its
// attribute tools handle float attributes; stratum numbers are exact up to 2^24.
inline constexpr const char* kRadiusAttribute = "radius";
inline constexpr const char* kStratumTypeAttribute = "stratum_type";    // 0 corner, 1 crease, 2 patch
inline constexpr const char* kStratumIndexAttribute = "stratum_index";  // corner, crease or patch number

// The layers one run added to the document; null where a run to its stage makes none.
struct ResultLayers {
  MeshModel* balls = nullptr;
  // To come with the library's seeds and cells (MeshResult grows them): the conforming surface,
  // faces coloured and labelled by the region pair they separate with their quality as per-face
  // quality (so MeshLab's histogram shows it), and the seeds, a point layer with label and radius
  // attributes. Each gets a field here and an add_..._layer beside add_balls_layer.
};

// Adds a point layer named "SOURCE VoroCrust balls" (SOURCE: the source layer's label without its
// extension and with no dot, so "bunny.off" gives "bunny VoroCrust balls") and makes it current:
// one vertex per ball centre, in the library's order (balls.csv's rows), with the radius as the
// float attribute "radius" and as vertex quality (so Colorize by vertex quality and the quality
// histogram work), the stratum as "stratum_type" and "stratum_index", and a colour per stratum
// type (corners red, creases yellow, patches grey-blue). It carries the source layer's
// transformation matrix.
MeshModel* add_balls_layer(MeshDocument& md, const std::vector<Ball>& balls, const MeshModel& source);

// Adds every layer a run up to `stage` yields. Today that is the balls layer; the surface and
// seeds layers join it for Stage::Cells when the library makes them. On failure the layers added
// so far are removed again and the exception goes on.
ResultLayers add_result_layers(MeshDocument& md, const MeshResult& result, Stage stage, const MeshModel& source);

}  // namespace vorocrust::meshlab
