// vorocrust/regions.hpp — the regions of space a surface cuts out, and the label of every side.
//
// label_regions(mesh) labels both sides of every face with the region of space it faces, for
// surfaces of any kind: one closed shell, nested shells, solids touching along faces or edges,
// edges shared by three or more faces (walls inside a box), sheets inside a box.
// - Faces around each edge are ordered by angle with exact predicates; the two sides bounding a
//   wedge between consecutive faces face one region. Sides so joined form shells, and shells of
//   separate parts are nested by the parity of ray crossings. Each connected region of space is
//   one piece; the unbounded piece is label 0.
// - Labels the input gives (mesh.face_regions: OBJ groups named "BACK|FRONT", PLY
//   back_region/front_region, one solid per input file) take precedence: a piece takes the label
//   any of its sides carries, and sides without one take their piece's. Two pieces may carry one
//   label (one material in two places). Two different labels on sides of one piece are an error,
//   Error(InvalidGeometry), naming both faces.
// - Label 0 is named as the input names the unbounded piece, else "outside". A piece no label
//   names gets a label of its own: "inside" when it is the only one of an unlabelled input,
//   "region<N>" (N its label) otherwise.
//
// Afterwards mesh.face_regions has a pair for every face and mesh.region_names a name for every
// label. The returned summary is indexed by label.
#pragma once

#include "vorocrust/api.hpp"

#include <cstddef>
#include <string>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

struct VOROCRUST_API RegionSummary {
  std::string name;
  std::size_t pieces = 0;  // connected regions of space with this label
  std::size_t sides = 0;   // face sides facing them
  double volume = 0;       // the bounded pieces' enclosed volume (label 0: its bounded pieces only)
};

VOROCRUST_API std::vector<RegionSummary> label_regions(SurfaceMesh& mesh);

// The summary label_regions gives, leaving `mesh` as it is (for reports on an input).
VOROCRUST_API std::vector<RegionSummary> find_regions(const SurfaceMesh& mesh);

// The volume of every region but the outside (label 0): what the materials fill.
VOROCRUST_API double materials_volume(const std::vector<RegionSummary>& regions);

}  // namespace vorocrust
