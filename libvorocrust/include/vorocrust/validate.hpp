// vorocrust/validate.hpp — what is wrong with an input surface, said with where.
//
// validate() checks a mesh that read_mesh() accepted: faces with a repeated corner or zero area,
// duplicate faces, faces whose orientation disagrees with a neighbour across a manifold edge,
// closed shells turned inside out, and self-intersections (found with a bounding-volume tree
// over the faces and decided by exact orientation predicates).
//
// Faces folded over their neighbours are unfolded in place (fix_folds), as the paper's sampling
// cannot cover a surface that turns back on itself over one face.
//
// Orientation problems are *fixed* in place (and reported as such) when `fix_orientation` is
// set: each patch of faces joined by manifold edges is made consistent, and a closed shell is
// turned so its normals point out of the volume it encloses. Everything else is only reported.
#pragma once

#include "vorocrust/api.hpp"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

struct VOROCRUST_API Finding {
  enum class Severity {
    Note,     // worth knowing, harmless
    Fixed,    // was wrong, has been repaired in place
    Warning,  // suspicious; meshing proceeds
    Error,    // meshing refuses this input
  };
  Severity severity = Severity::Note;
  std::string code;     // stable identifier, e.g. "self-intersection"
  std::string message;  // one line, naming faces and source lines
  std::size_t count = 0;                // how many instances in total
  std::vector<std::size_t> faces;       // the faces concerned (at most max_listed)
  std::vector<std::pair<std::size_t, std::size_t>> face_pairs;  // for pairwise findings
};

VOROCRUST_API const char* to_string(Finding::Severity severity) noexcept;

struct VOROCRUST_API ValidationOptions {
  bool fix_orientation = true;
  // Faces folded over all their neighbours (an inverted triangle of a decimated scan, the surface
  // turning back on itself over one face) are unfolded by moving their free vertices to the
  // centroid of their neighbours; reported as fixed, or as an error where that does not unfold
  // them. No fold-free surface changes. Needs fix_orientation (the normals are compared).
  bool fix_folds = true;
  bool check_self_intersections = true;
  // Whether intersecting faces are an Error (meshing refuses them) or a Warning (the mesher
  // resolves them, MeshOptions::self_intersections).
  bool self_intersections_are_errors = true;
  std::size_t max_listed = 20;  // faces or pairs named per finding
};

struct VOROCRUST_API ValidationReport {
  std::vector<Finding> findings;
  bool has_errors() const;
  const Finding* find(const std::string& code) const;
};

VOROCRUST_API ValidationReport validate(SurfaceMesh& mesh, const ValidationOptions& options = {});

}  // namespace vorocrust
