// Turning MeshLab layers into the library's input surface.
#pragma once

#include <vector>

#include "vorocrust/surface_mesh.hpp"

class MeshModel;

namespace vorocrust::meshlab {

// One model from one or several layers, keeping every live face as it is: faces around
// non-manifold edges, open boundaries and separate components all survive; deleted faces and
// vertices are skipped. Coordinates are MeshLab's (single precision), widened exactly; the
// layer's transformation matrix is not applied, as MeshLab's own filters do not apply it.
//
// Vertices: every live vertex of each layer, in the layer's order, so a single layer keeps
// MeshLab's vertex numbering when it has no deleted vertex. Several layers merge as
// vorocrust::merge_surfaces merges input files: a vertex of a later layer with exactly the
// coordinates of one of an earlier layer is shared, a face two layers share is one face, and
// a layer that is one closed surface is a solid, the material named after the layer.
//
// Face groups keep the face selection: a layer's unselected faces form the group named after
// the layer, its selected faces the group "LAYER/selected"; a group is made only when it has
// faces. Each group's source_file is the layer's file (its label when it has none), so
// messages about faces name the layer.
//
// Throws vorocrust::Error(InvalidGeometry) when a layer has no live face or a live vertex has a
// NaN or infinite coordinate (the library's readers refuse those too), naming the layer and the
// vertex.
SurfaceMesh surface_from_layers(const std::vector<const MeshModel*>& layers);

}  // namespace vorocrust::meshlab
