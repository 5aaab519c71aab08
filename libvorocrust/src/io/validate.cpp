#include "vorocrust/validate.hpp"

#include <algorithm>
#include <cstdio>
#include <deque>

#include "core/c_format.hpp"
#include "core/edge_topology.hpp"
#include "core/surface_measures.hpp"
#include "geometry/predicates.hpp"
#include "geometry/self_intersections.hpp"
#include "io/unfold_faces.hpp"

namespace vorocrust {

namespace {

// A triangle has zero area exactly when its corners are collinear, i.e. when all three of its
// axis-aligned projections are degenerate; decided exactly.
bool has_zero_area(const SurfaceMesh& mesh, const Triangle& t) {
  const Point &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
  for (int axis = 0; axis < 3; ++axis) {
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    if (geometry::orient2d(a[i], a[j], b[i], b[j], c[i], c[j]) != 0) return false;
  }
  return true;
}

std::string list_faces(const SurfaceMesh& mesh, const std::vector<std::size_t>& faces, std::size_t total) {
  std::string text;
  for (std::size_t k = 0; k < faces.size(); ++k) text += (k ? ", " : "") + describe_face(mesh, faces[k]);
  if (total > faces.size()) text += ", and " + std::to_string(total - faces.size()) + " more";
  return text;
}

std::string list_pairs(const SurfaceMesh& mesh, const std::vector<std::pair<std::size_t, std::size_t>>& pairs,
                       std::size_t total) {
  std::string text;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    text += (k ? "; " : "") + describe_face(mesh, pairs[k].first) + " and " + describe_face(mesh, pairs[k].second);
  }
  if (total > pairs.size()) text += "; and " + std::to_string(total - pairs.size()) + " more pairs";
  return text;
}

Finding face_finding(const SurfaceMesh& mesh, Finding::Severity severity, std::string code, const std::string& what,
                     const std::vector<std::size_t>& faces, std::size_t max_listed) {
  Finding finding{severity, std::move(code), {}, faces.size(), {}, {}};
  finding.faces.assign(faces.begin(), faces.begin() + std::min(faces.size(), max_listed));
  finding.message = std::to_string(faces.size()) + " " + what + ": " + list_faces(mesh, finding.faces, faces.size());
  return finding;
}

Finding pair_finding(const SurfaceMesh& mesh, Finding::Severity severity, std::string code, const std::string& what,
                     const std::vector<std::pair<std::size_t, std::size_t>>& pairs, std::size_t max_listed) {
  Finding finding{severity, std::move(code), {}, pairs.size(), {}, {}};
  finding.face_pairs.assign(pairs.begin(), pairs.begin() + std::min(pairs.size(), max_listed));
  finding.message = std::to_string(pairs.size()) + " " + what + ": " + list_pairs(mesh, finding.face_pairs, pairs.size());
  return finding;
}

void check_zero_area(const SurfaceMesh& mesh, const ValidationOptions& options, ValidationReport& report) {
  std::vector<std::size_t> faces;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (has_zero_area(mesh, mesh.triangles[f])) faces.push_back(f);
  }
  if (!faces.empty()) {
    report.findings.push_back(face_finding(mesh, Finding::Severity::Error, "zero-area-face",
                                           "faces with zero area (collinear corners)", faces, options.max_listed));
  }
}

// Faces with the same three corners, within one file or between two.
void check_duplicates(const SurfaceMesh& mesh, const ValidationOptions& options, ValidationReport& report) {
  std::vector<std::pair<Triangle, std::size_t>> keyed(mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    Triangle t = mesh.triangles[f];
    std::sort(t.begin(), t.end());
    keyed[f] = {t, f};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::pair<std::size_t, std::size_t>> within, between;
  for (std::size_t k = 1; k < keyed.size(); ++k) {
    if (keyed[k].first != keyed[k - 1].first) continue;
    const std::size_t a = keyed[k - 1].second, b = keyed[k].second;
    const bool same_file = mesh.groups[mesh.face_group[a]].source_file == mesh.groups[mesh.face_group[b]].source_file;
    (same_file ? within : between).emplace_back(a, b);
  }
  if (!within.empty()) {
    report.findings.push_back(pair_finding(mesh, Finding::Severity::Error, "duplicate-face",
                                           "pairs of duplicate faces (same three corners)", within, options.max_listed));
  }
  // read_meshes() and merge_surfaces() keep one copy of a face two parts share, the interface
  // between their solids; two copies left (parts put together otherwise) would be two faces on
  // one triangle, which the refinement cannot cover.
  if (!between.empty()) {
    report.findings.push_back(pair_finding(mesh, Finding::Severity::Error, "shared-face",
                                           "pairs of faces on one triangle from two parts (merge the parts with "
                                           "merge_surfaces, which keeps one face between their solids)",
                                           between, options.max_listed));
  }
}

// Makes every patch of faces joined by manifold edges consistently oriented (flipping the
// minority), then turns closed shells so their normals point out of the volume they enclose.
void fix_orientation(SurfaceMesh& mesh, const EdgeTopology& topo, const ValidationOptions& options,
                     ValidationReport& report) {
  const std::size_t n = mesh.triangles.size();
  std::vector<std::int8_t> flip(n, 0);
  std::vector<bool> seen(n, false);
  std::vector<std::size_t> flipped, non_orientable, inverted_shells;
  std::size_t shells = 0;
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (seen[seed]) continue;
    std::vector<Index> patch{static_cast<Index>(seed)};
    seen[seed] = true;
    bool closed = true, orientable = true;
    for (std::size_t head = 0; head < patch.size(); ++head) {
      const Index f = patch[head];
      for (Index e : topo.face_edges[f]) {
        if (topo.valence(e) != 2) {
          closed = false;
          continue;
        }
        const auto faces = topo.faces_of(e);
        const Index g = faces[0] == f ? faces[1] : faces[0];
        const auto [a, b] = topo.edges[e];
        // Consistent neighbours run along their common edge in opposite directions.
        const int df = edge_direction(mesh.triangles[f], a, b) * (flip[f] ? -1 : 1);
        const int dg = edge_direction(mesh.triangles[g], a, b);
        const std::int8_t wanted = (df == dg) ? 1 : 0;
        if (!seen[g]) {
          seen[g] = true;
          flip[g] = wanted;
          patch.push_back(g);
        } else if (flip[g] != wanted) {
          orientable = false;
        }
      }
    }
    const std::size_t count = static_cast<std::size_t>(std::count_if(patch.begin(), patch.end(), [&](Index f) { return flip[f]; }));
    if (2 * count > patch.size()) {
      for (Index f : patch) flip[f] = !flip[f];
    }
    if (!orientable) {
      non_orientable.push_back(seed);
      for (Index f : patch) flip[f] = 0;  // leave a non-orientable patch as it was
      continue;
    }
    for (Index f : patch) {
      if (flip[f]) {
        mesh.flip(f);
        flipped.push_back(f);
      }
    }
    if (closed) {
      ++shells;
      if (enclosed_volume(mesh, patch) < 0) {
        for (Index f : patch) mesh.flip(f);
        inverted_shells.push_back(seed);
      }
    }
  }
  std::sort(flipped.begin(), flipped.end());
  if (!flipped.empty()) {
    report.findings.push_back(face_finding(mesh, Finding::Severity::Fixed, "inconsistent-orientation",
                                           "faces flipped to agree with their neighbours", flipped, options.max_listed));
  }
  if (!inverted_shells.empty()) {
    Finding f = face_finding(mesh, Finding::Severity::Fixed, "inward-shell",
                             "closed shells turned so their normals point outward (shell containing", inverted_shells,
                             options.max_listed);
    f.message += ")";
    report.findings.push_back(std::move(f));
  }
  if (!non_orientable.empty()) {
    report.findings.push_back(face_finding(mesh, Finding::Severity::Warning, "non-orientable",
                                           "non-orientable patches (Moebius-like), left as they are, containing",
                                           non_orientable, options.max_listed));
  }
}

void check_self_intersections(const SurfaceMesh& mesh, const ValidationOptions& options, ValidationReport& report) {
  const auto pairs = geometry::find_self_intersections(mesh);
  if (!pairs.empty()) {
    const auto severity = options.self_intersections_are_errors ? Finding::Severity::Error : Finding::Severity::Warning;
    Finding f = pair_finding(mesh, severity, "self-intersection", "pairs of intersecting faces", pairs, options.max_listed);
    report.findings.push_back(std::move(f));
  }
}

}  // namespace

const char* to_string(Finding::Severity severity) noexcept {
  switch (severity) {
    case Finding::Severity::Note: return "note";
    case Finding::Severity::Fixed: return "fixed";
    case Finding::Severity::Warning: return "warning";
    case Finding::Severity::Error: return "error";
  }
  return "error";
}

bool ValidationReport::has_errors() const {
  return std::any_of(findings.begin(), findings.end(),
                     [](const Finding& f) { return f.severity == Finding::Severity::Error; });
}

const Finding* ValidationReport::find(const std::string& code) const {
  for (const Finding& f : findings) {
    if (f.code == code) return &f;
  }
  return nullptr;
}

std::string number_text(double x) { return c_format("%.3g", x); }

// Faces folded over all their neighbours, unfolded where moving their vertices does it.
void fix_folds(SurfaceMesh& mesh, const ValidationOptions& options, ValidationReport& report) {
  const io::Unfolding unfolding = io::unfold_faces(mesh);
  if (unfolding.folded.empty()) return;
  std::vector<std::size_t> folded(unfolding.folded.begin(), unfolding.folded.end());
  if (!unfolding.remaining.empty()) {
    std::vector<std::size_t> remaining(unfolding.remaining.begin(), unfolding.remaining.end());
    report.findings.push_back(face_finding(
        mesh, Finding::Severity::Error, "folded-face",
        "faces folded over all their neighbours (the surface turns back on itself over them) that moving their "
        "vertices does not unfold; repair the input there",
        remaining, options.max_listed));
    return;
  }
  Finding finding = face_finding(mesh, Finding::Severity::Fixed, "folded-face",
                                 "faces folded over all their neighbours (the surface turned back on itself over them)",
                                 folded, options.max_listed);
  finding.message += "; unfolded by moving " + std::to_string(unfolding.moved_vertices) +
                     " vertices to where their faces bend least, by at most " +
                     number_text(unfolding.largest_move);
  report.findings.push_back(std::move(finding));
}

ValidationReport validate(SurfaceMesh& mesh, const ValidationOptions& options) {
  ValidationReport report;
  check_zero_area(mesh, options, report);
  check_duplicates(mesh, options, report);
  if (options.fix_orientation) fix_orientation(mesh, build_edge_topology(mesh), options, report);
  if (options.fix_orientation && options.fix_folds) fix_folds(mesh, options, report);
  if (options.check_self_intersections) check_self_intersections(mesh, options, report);
  return report;
}

}  // namespace vorocrust
