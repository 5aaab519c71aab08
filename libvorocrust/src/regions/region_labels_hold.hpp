// Internal: whether the region labels a surface carries still hold after its faces moved.
//
// Smoothing carries each face's pair of labels from the face it came from, but it may move a
// shell across another one without any faces crossing at the end (Loop's rules pull a coarse
// icosahedron inside a sphere it used to enclose). label_regions, run afresh on a copy, then finds
// two labels on one region of space, or the labels in other places. The labels hold when it
// finds every side facing the region its label names, and the same region unbounded.
#pragma once

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

// `mesh` carries a label on every side (label_regions ran on it or on the mesh it came from); a
// mesh without labels has none to break.
bool region_labels_hold(const SurfaceMesh& mesh);

}  // namespace vorocrust
