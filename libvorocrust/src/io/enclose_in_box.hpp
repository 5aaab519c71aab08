// Internal: the volume around open sheets (paper section 3, Figure 17). A terrain, fault or
// horizon bounds no volume by itself; the domain is a box around it whose six sides join the
// surface, so the refinement protects them like any other face and the sheet splits the cells
// that touch it.
//
// enclose_in_box(input, box) returns the input with the box's twelve triangles appended (group
// "box", normals pointing out of the box). What lay outside every material inside the box (region
// 0, or every side of an unlabelled input) becomes the region "domain"; the box's faces separate
// "domain" (behind) from the outside (region 0, in front). So an unlabelled sheet is one
// material on both of its sides, and a labelled model keeps its materials inside the domain.
//
// needs_box(input) says whether an input must be enclosed when no box is given: it has an edge
// of one face (an open sheet). default_box(input) is its bounding box grown on every side by a
// tenth of its diagonal, room enough for the protecting balls of the sheet and of the box not
// to crowd each other.
//
// holds_its_box(input) says whether an input already holds a box around all of it, as
// enclose_in_box makes it: faces lying flat on the six sides of its bounding box cover each side
// whole (a run's smoothed_surface.ply, whose box smoothing may have split but not moved). Such an
// input needs no other box, though its sheets have open edges.
//
// box_faces(mesh) flags the faces enclose_in_box added (the group it names "box", from no file),
// also after steps that keep each face's group (cutting along self-intersections); all false
// when there are none.
//
// Throws Error(InvalidGeometry) naming the first vertex that does not lie strictly inside the
// box, and Error(Usage) for a box whose lower corner is not below its upper corner.
#pragma once

#include <vector>

#include "geometry/box_tree.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

bool needs_box(const SurfaceMesh& input);
bool holds_its_box(const SurfaceMesh& input);
geometry::Box default_box(const SurfaceMesh& input);
SurfaceMesh enclose_in_box(const SurfaceMesh& input, const geometry::Box& box);
std::vector<bool> box_faces(const SurfaceMesh& mesh);

}  // namespace vorocrust
