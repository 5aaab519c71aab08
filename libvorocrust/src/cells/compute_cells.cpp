#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <utility>

#include "cells/cell_faces.hpp"
#include "cells/growing_cells.hpp"
#include "cells/renumber_points.hpp"
#include "core/memory.hpp"
#include "geometry/measure_cells.hpp"
#include "geometry/polygon_measures.hpp"
#include "cells/voronoi_cells.hpp"
#include "cells/weld_vertices.hpp"
#include "geometry/curve_order.hpp"
#include "geometry/cell_spheres.hpp"
#include "vorocrust/cells.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust {
namespace {

using cells::CellFaces;

bool is_material(std::int32_t region, const std::vector<std::int32_t>& materials) {
  return materials.empty() ? region > 0 : std::find(materials.begin(), materials.end(), region) != materials.end();
}

void check_seeds(const std::vector<Seed>& seeds, const std::vector<std::int32_t>& cell_of_seed) {
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    if (!seeds[s].position.allFinite()) {
      throw Error(Error::Kind::InvalidGeometry, "seed " + std::to_string(s) + " has a coordinate that is not a finite number");
    }
  }
  std::vector<Index> order(seeds.size());
  std::iota(order.begin(), order.end(), Index{0});
  const auto key = [&](Index s) {
    const Point& p = seeds[s].position;
    return std::tuple(p.x(), p.y(), p.z(), s);
  };
  std::sort(order.begin(), order.end(), [&](Index a, Index b) { return key(a) < key(b); });
  for (std::size_t k = 1; k < order.size(); ++k) {
    const Index a = order[k - 1], b = order[k];
    if (seeds[a].position == seeds[b].position && (cell_of_seed[a] != kNoCell || cell_of_seed[b] != kNoCell)) {
      throw Error(Error::Kind::InvalidGeometry, "seeds " + std::to_string(std::min(a, b)) + " and " +
                                                    std::to_string(std::max(a, b)) + " are at the same place");
    }
  }
}

// Cells are computed with the seeds about one unit apart, the scale of Voro++'s tolerances. The
// scale is a power of two, so that a few seeds more leave the frame as it was (GrowingCells).
cells::Frame make_frame(const std::vector<Seed>& seeds) {
  cells::Frame frame;
  Eigen::AlignedBox3d box;
  for (const Seed& s : seeds) box.extend(s.position);
  frame.centre = box.center();
  const double n = static_cast<double>(seeds.size());
  const double spacing = std::cbrt(box.volume() / n);
  const double scale = spacing > 0 ? spacing : box.diagonal().norm() > 0 ? box.diagonal().norm() / n : 1.0;
  frame.scale = std::exp2(std::round(std::log2(scale)));
  frame.original.reserve(seeds.size());
  frame.normalized.reserve(seeds.size());
  for (const Seed& s : seeds) {
    frame.original.push_back(s.position);
    frame.normalized.push_back((s.position - frame.centre) / frame.scale);
  }
  return frame;
}

// The index of the face of `faces` toward `seed`, if any.
std::optional<std::size_t> face_toward(const CellFaces& faces, Index seed) {
  const auto it = std::find(faces.neighbours.begin(), faces.neighbours.end(), static_cast<std::int32_t>(seed));
  if (it == faces.neighbours.end()) return std::nullopt;
  return static_cast<std::size_t>(it - faces.neighbours.begin());
}

// Whether polygon a is polygon b run backwards, from any start.
bool is_reverse(const Index* a, const Index* b, std::size_t n) {
  const std::size_t at = static_cast<std::size_t>(std::find(b, b + n, a[0]) - b);
  if (at == n) return false;
  for (std::size_t k = 1; k < n; ++k) {
    if (a[k] != b[(at + n - k) % n]) return false;
  }
  return true;
}

[[noreturn]] void fail_on_lowest(const std::vector<char>& failed, const std::vector<Index>& cell_seeds,
                                 const std::string& what) {
  Index lowest = std::numeric_limits<Index>::max();
  for (std::size_t c = 0; c < failed.size(); ++c) {
    if (failed[c]) lowest = std::min(lowest, cell_seeds[c]);
  }
  throw Error(Error::Kind::Internal, "cell of seed " + std::to_string(lowest) + " " + what);
}

struct Assembly {
  const std::vector<Seed>& seeds;
  const std::vector<Index>& cell_seeds;
  const std::vector<std::int32_t>& cell_of_seed;
  const std::vector<std::uint32_t>& number;  // per cell, its number in the mesh
  std::vector<CellFaces> faces;              // per cell, over welded points

  // The owner of a face between two cells is the one of the lower seed, which is the lower
  // number in the mesh.
  bool owns(std::size_t c, std::int32_t neighbour) const {
    return cell_of_seed[static_cast<std::size_t>(neighbour)] == kNoCell ||
           static_cast<Index>(neighbour) > cell_seeds[c];
  }

  // Marks failed[c] where cell c and a neighbour do not see their common face alike: the owner
  // finds no face toward it on the other side, or the other finds its own face not the owner's
  // run backwards. Before build, which allocates every face, so that a weld that fails costs no
  // mesh.
  void check(std::vector<char>& failed) const {
    tbb::parallel_for(std::size_t{0}, cell_seeds.size(), [&](std::size_t c) {
      const CellFaces& mine = faces[c];
      const Index seed = cell_seeds[c];
      for (std::size_t f = 0; f < mine.num_faces() && !failed[c]; ++f) {
        const std::int32_t d = cell_of_seed[static_cast<std::size_t>(mine.neighbours[f])];
        if (d == kNoCell) continue;
        const CellFaces& theirs = faces[static_cast<std::size_t>(d)];
        const std::optional<std::size_t> g = face_toward(theirs, seed);
        if (owns(c, mine.neighbours[f])) {
          failed[c] = !g;
          continue;
        }
        const std::size_t size = mine.starts[f + 1] - mine.starts[f];
        failed[c] = !g || theirs.starts[*g + 1] - theirs.starts[*g] != size ||
                    !is_reverse(mine.points.data() + mine.starts[f], theirs.points.data() + theirs.starts[*g], size);
      }
    });
  }

  // Every face once, owned by the lower cell, and listed in the order of the owners' numbers;
  // each cell's face list, as mesh.cells[number[c]] for cell c. The cells passed check. Built in
  // the order of the numbers, so that the faces' polygons lie in memory in the order of the list.
  void build(VoronoiMesh& mesh) const {
    const std::size_t n = cell_seeds.size();
    std::vector<std::size_t> numbered(n);
    for (std::size_t c = 0; c < n; ++c) numbered[number[c]] = c;
    std::vector<std::size_t> first_face(n, 0);  // per cell
    std::size_t total = 0;
    for (const std::size_t c : numbered) {
      first_face[c] = total;
      for (std::int32_t s : faces[c].neighbours) total += owns(c, s);
    }
    mesh.faces.resize(total);
    mesh.cells.resize(n);
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t m) {
      const std::size_t c = numbered[m];
      const CellFaces& mine = faces[c];
      VoronoiCell& cell = mesh.cells[m];
      cell.seed = cell_seeds[c];
      cell.site = seeds[cell.seed].position;
      cell.region = seeds[cell.seed].region;
      cell.seed_kind = seeds[cell.seed].kind;
      cell.faces.reserve(mine.num_faces());
      std::size_t next = first_face[c];
      for (std::size_t f = 0; f < mine.num_faces(); ++f) {
        const Index* polygon = mine.points.data() + mine.starts[f];
        const std::size_t size = mine.starts[f + 1] - mine.starts[f];
        const auto across = static_cast<Index>(mine.neighbours[f]);
        if (owns(c, mine.neighbours[f])) {
          VoronoiFace& face = mesh.faces[next];
          face.points.assign(polygon, polygon + size);
          face.owner = static_cast<std::int32_t>(number[c]);
          face.neighbour = cell_of_seed[across] == kNoCell
                               ? kNoCell
                               : static_cast<std::int32_t>(number[static_cast<std::size_t>(cell_of_seed[across])]);
          face.owner_seed = cell.seed;
          face.neighbour_seed = across;
          face.regions = {cell.region, seeds[across].region};
          cell.faces.push_back(static_cast<Index>(next++));
          continue;
        }
        const auto d = static_cast<std::size_t>(cell_of_seed[across]);
        const std::size_t g = *face_toward(faces[d], cell.seed);
        std::size_t id = first_face[d];
        for (std::size_t k = 0; k < g; ++k) id += owns(d, faces[d].neighbours[k]);
        cell.faces.push_back(static_cast<Index>(id));
      }
    });
  }
};

}  // namespace

namespace cells {

GrowingCells::GrowingCells(const std::vector<Seed>& seeds, const CellsOptions& options)
    : seeds_(seeds), options_(options), cell_of_seed_(seeds.size(), kNoCell) {
  for (std::size_t s = 0; s < seeds.size(); ++s) add_cell(s);
  if (cell_seeds_.empty()) {
    throw Error(Error::Kind::InvalidGeometry, "no seed has a material region, so there is no cell to make");
  }
  check_seeds(seeds_, cell_of_seed_);
  cut_all();
}

void GrowingCells::add_cell(std::size_t s) {
  if (!is_material(seeds_[s].region, options_.materials)) return;
  cell_of_seed_[s] = static_cast<std::int32_t>(cell_seeds_.size());
  cell_seeds_.push_back(static_cast<Index>(s));
}

template <class Work>
void GrowingCells::in_arena(Work&& work) const {
  tbb::task_arena arena(options_.threads > 0 ? options_.threads : tbb::task_arena::automatic);
  arena.execute(std::forward<Work>(work));
}

void GrowingCells::cut_all() {
  in_arena([&] {
    frame_ = make_frame(seeds_);
    raw_ = compute_voronoi_cells(frame_.normalized, cell_seeds_);
  });
  cut_since_.assign(raw_.size(), 1);
  ratio_stale_.assign(raw_.size(), 1);
}

void GrowingCells::add_seeds(const std::vector<Seed>& seeds) {
  const std::size_t old_count = seeds_.size();
  if (seeds.size() < old_count) throw Error(Error::Kind::Internal, "GrowingCells: seeds may only be added");
  if (seeds.size() == old_count) return;
  seeds_.insert(seeds_.end(), seeds.begin() + static_cast<std::ptrdiff_t>(old_count), seeds.end());
  cell_of_seed_.resize(seeds_.size(), kNoCell);
  const std::size_t old_cells = cell_seeds_.size();
  for (std::size_t s = old_count; s < seeds_.size(); ++s) add_cell(s);
  check_seeds(seeds_, cell_of_seed_);
  Frame frame = make_frame(seeds_);
  if (frame.centre != frame_.centre || frame.scale != frame_.scale) {  // another frame: every cell changes
    cut_all();
    return;
  }
  frame_ = std::move(frame);
  in_arena([&] {
    std::vector<Index> added(seeds_.size() - old_count);
    std::iota(added.begin(), added.end(), static_cast<Index>(old_count));
    std::vector<std::size_t> which = cells_reached(frame_.normalized, cell_seeds_, raw_, added);
    for (std::size_t c = old_cells; c < cell_seeds_.size(); ++c) which.push_back(c);
    raw_.resize(cell_seeds_.size());
    recompute_voronoi_cells(frame_.normalized, cell_seeds_, which, 0, raw_);
    cut_since_.resize(raw_.size(), 1);
    ratio_stale_.resize(raw_.size(), 1);
    for (std::size_t c : which) cut_since_[c] = ratio_stale_[c] = 1;
  });
}

namespace {

// The cells marked and the cells next to them (a face between two cells is measured, welded
// and assembled from both).
std::vector<char> with_neighbours(const std::vector<RawCell>& raw, const std::vector<std::int32_t>& cell_of_seed,
                                  const std::vector<char>& marked) {
  std::vector<char> in(raw.size(), 0);
  for (std::size_t c = 0; c < raw.size(); ++c) {
    if (!marked[c]) continue;
    in[c] = 1;
    for (std::int32_t n : raw[c].neighbours) {
      const std::int32_t d = n >= 0 ? cell_of_seed[static_cast<std::size_t>(n)] : kNoCell;
      if (d != kNoCell) in[static_cast<std::size_t>(d)] = 1;
    }
  }
  return in;
}

// Whether three points of face f of a cell stand apart by more than welding's first tolerance
// unites: the faces that welding leaves with two points or one, it drops. (Welding also unites
// points in chains across cells, and at higher tolerances in its fallbacks; a face it drops so
// is still listed here, which costs a repair seed at most, where a face missed would stay skew.)
bool spans_an_area(const RawCell& cell, std::size_t f, const Point& seed) {
  constexpr double kApart = 1e-9;
  std::array<const Point*, 3> apart{};
  std::size_t found = 0;
  for (std::uint32_t k = cell.starts[f]; k < cell.starts[f + 1] && found < 3; ++k) {
    const Point& p = cell.vertices[cell.cycles[k]];
    const double tolerance = weld_tolerance(p, seed, kApart);
    if (std::all_of(apart.begin(), apart.begin() + found, [&](const Point* q) { return (p - *q).norm() > tolerance; })) {
      apart[found++] = &p;
    }
  }
  return found == 3;
}

std::size_t face_size(const RawCell& cell, std::size_t f) { return std::size_t{cell.starts[f + 1] - cell.starts[f]}; }

// The accessor of face f's points in order, for polygon_measures.hpp.
auto face_points(const RawCell& cell, std::size_t f) {
  return [&cell, f](std::size_t k) -> const Point& { return cell.vertices[cell.cycles[cell.starts[f] + k]]; };
}

Point centroid_of(const RawCell& cell) {
  double volume = 0;
  Point moment = Point::Zero();
  for (std::size_t f = 0; f < cell.num_faces(); ++f) {
    geometry::add_cone(cell.vertices.front(), face_size(cell, f), face_points(cell, f), true, volume, moment);
  }
  return moment / volume;
}

// An upper bound on a cell's aspect ratio from its seed `s`, which lies inside it: the ball about
// s through the farthest vertex encloses the cell, and the ball about s to the nearest face plane
// lies inside it. Most cells are well below a bound worth splitting at, and this spares them the
// two spheres.
double aspect_ratio_above(const RawCell& cell, const Point& s) {
  double farthest = 0, nearest = std::numeric_limits<double>::infinity();
  for (const Point& v : cell.vertices) farthest = std::max(farthest, (v - s).squaredNorm());
  for (std::size_t f = 0; f < cell.num_faces(); ++f) {
    const FaceGeometry g = geometry::polygon_geometry(face_size(cell, f), face_points(cell, f));
    nearest = std::min(nearest, std::abs(g.normal.dot(g.centroid - s)));
  }
  return nearest > 0 ? std::sqrt(farthest) / nearest : std::numeric_limits<double>::infinity();
}

}  // namespace

std::vector<LongCell> GrowingCells::long_cells(double bound) {
  if (bound != ratio_bound_) std::fill(ratio_stale_.begin(), ratio_stale_.end(), 1);
  ratio_bound_ = bound;
  aspect_ratio_.resize(raw_.size(), 0);
  ratio_stale_.resize(raw_.size(), 1);
  in_arena([&] {
    tbb::parallel_for(std::size_t{0}, raw_.size(), [&](std::size_t c) {
      if (!ratio_stale_[c]) return;
      const RawCell& cell = raw_[c];
      // Within the bound by the cheap figure, with a margin for its rounding: no need of the
      // exact one.
      aspect_ratio_[c] = aspect_ratio_above(cell, frame_.normalized[cell_seeds_[c]]);
      if (aspect_ratio_[c] * (1 + 1e-9) <= bound) return;
      aspect_ratio_[c] =
          geometry::cell_spheres(cell.vertices, cell.num_faces(), [&](std::size_t f) { return face_size(cell, f); },
                                [&](std::size_t f, std::size_t k) -> const Point& { return face_points(cell, f)(k); })
              .aspect_ratio();
    });
  });
  std::fill(ratio_stale_.begin(), ratio_stale_.end(), 0);
  std::vector<LongCell> out;
  for (std::size_t c = 0; c < raw_.size(); ++c) {
    if (!(aspect_ratio_[c] > bound)) continue;
    const Point& seed = frame_.normalized[cell_seeds_[c]];
    const auto farther = [&](const Point& a, const Point& b) { return (a - seed).squaredNorm() < (b - seed).squaredNorm(); };
    const Point& tip = *std::max_element(raw_[c].vertices.begin(), raw_[c].vertices.end(), farther);
    out.push_back({cell_seeds_[c], frame_.centre + frame_.scale * centroid_of(raw_[c]), frame_.centre + frame_.scale * tip});
  }
  return out;
}

std::vector<CutFace> GrowingCells::skew_faces(double threshold) {
  const auto point_at = face_points;
  const auto size = face_size;
  const auto original = [&](const Point& p) { return Point(frame_.centre + frame_.scale * p); };  // out of the frame
  if (threshold != skew_threshold_) std::fill(cut_since_.begin(), cut_since_.end(), 1);
  skew_threshold_ = threshold;
  centroid_.resize(raw_.size());
  owned_skew_.resize(raw_.size());
  // The faces to measure again: those of the cells cut since, and of the cells next to them.
  const std::vector<char> measure = with_neighbours(raw_, cell_of_seed_, cut_since_);
  in_arena([&] {
    tbb::parallel_for(std::size_t{0}, raw_.size(), [&](std::size_t c) {
      if (cut_since_[c]) centroid_[c] = centroid_of(raw_[c]);
    });
    tbb::parallel_for(std::size_t{0}, raw_.size(), [&](std::size_t c) {
      if (!measure[c]) return;
      const RawCell& cell = raw_[c];
      std::vector<CutFace>& found = owned_skew_[c];
      found.clear();
      for (std::size_t f = 0; f < cell.num_faces(); ++f) {
        const std::int32_t across = cell.neighbours[f];
        const std::int32_t d = across >= 0 ? cell_of_seed_[static_cast<std::size_t>(across)] : kNoCell;
        if (d != kNoCell && d < static_cast<std::int32_t>(c)) continue;  // the lower cell has it
        if (!(spans_an_area(cell, f, frame_.normalized[cell_seeds_[c]]))) continue;  // welded away
        CutFace face{cell_seeds_[c], across, d != kNoCell, geometry::polygon_geometry(size(cell, f), point_at(cell, f)), 0};
        const std::optional<Point> neighbour =
            d != kNoCell ? std::optional<Point>(centroid_[static_cast<std::size_t>(d)]) : std::nullopt;
        face.skewness = geometry::polygon_skewness(size(cell, f), point_at(cell, f), face.geometry, centroid_[c], neighbour);
        if (!(face.skewness > threshold)) continue;
        face.geometry.centroid = original(face.geometry.centroid);
        face.geometry.area *= frame_.scale * frame_.scale;
        face.owner_centroid = original(centroid_[c]);
        if (neighbour) face.neighbour_centroid = original(*neighbour);
        found.push_back(face);
      }
    });
  });
  std::fill(cut_since_.begin(), cut_since_.end(), 0);
  std::vector<CutFace> out;
  for (const std::vector<CutFace>& list : owned_skew_) out.insert(out.end(), list.begin(), list.end());
  return out;
}

namespace {

// Welds the cells `raw` of `cell_seeds` (cell_of_seed: per seed, its index among them or kNoCell)
// and marks in the result each cell that is not closed after welding or sees a common face
// differently from its neighbour; when none is marked, assembles them into `mesh` (else `mesh`
// holds the welded points only), cell c as mesh.cells[number[c]].
// Faces toward seeds that have no cell here are boundary faces, checked by no one.
// With Raw::Release, the cells as cut are freed once none is marked, before the mesh is built:
// they take as many bytes as the mesh, and a weld that succeeded needs them no more.
enum class Raw { Keep, Release };
std::vector<char> weld_and_assemble(const std::vector<Seed>& seeds, const Frame& frame, std::vector<RawCell>& raw,
                                    const std::vector<Index>& cell_seeds, const std::vector<std::int32_t>& cell_of_seed,
                                    const std::vector<std::uint32_t>& number, const std::vector<double>& tolerance,
                                    Raw after, VoronoiMesh& mesh, bool& closed) {
  Assembly assembly{seeds, cell_seeds, cell_of_seed, number, std::vector<CellFaces>(raw.size())};
  std::vector<char> failed(raw.size(), 0);
  mesh = VoronoiMesh{};
  {
    WeldedVertices welded = weld_vertices(raw, cell_seeds, cell_of_seed, frame, tolerance);
    tbb::parallel_for(std::size_t{0}, raw.size(), [&](std::size_t c) {
      std::optional<CellFaces> f = welded_faces(raw[c], welded.first_instance[c], welded.point_of);
      if (f) assembly.faces[c] = std::move(*f);
      else failed[c] = 1;
    });
    mesh.points = std::move(welded.points);
  }
  closed = std::count(failed.begin(), failed.end(), 1) == 0;
  if (closed) {
    assembly.check(failed);
    // Cells that disagree only by points splitting an edge on one side agree without them.
    const auto disagree = [&] { return std::count(failed.begin(), failed.end(), 1) > 0; };
    if (disagree() && cells::drop_edge_points(assembly.faces, mesh.points.size()) > 0) {
      std::fill(failed.begin(), failed.end(), 0);
      assembly.check(failed);
    }
    if (!disagree()) {
      if (after == Raw::Release) std::vector<RawCell>().swap(raw);
      assembly.build(mesh);
    }
  }
  return failed;
}

// The cells with an edge shorter than kNearlyDegenerate of its vertices' empty spheres (welding
// unites points within 1e-9 of them, and its fallbacks within up to 1e-6): where Voro++ resolved
// a degenerate vertex into a tiny edge, which a neighbour may have resolved otherwise.
std::vector<std::size_t> near_degenerate(const std::vector<RawCell>& raw) {
  constexpr double kNearlyDegenerate = 1e-6;
  std::vector<std::size_t> out;
  for (std::size_t c = 0; c < raw.size(); ++c) {
    if (raw[c].shortest_edge2 <= kNearlyDegenerate * kNearlyDegenerate) out.push_back(c);
  }
  return out;
}

}  // namespace

VoronoiMesh GrowingCells::mesh() const& {
  return assemble([this](std::size_t c) { return raw_[c]; });
}

VoronoiMesh GrowingCells::mesh() && {
  return assemble([this](std::size_t c) { return std::move(raw_[c]); });
}

template <class Cell>
VoronoiMesh GrowingCells::assemble(Cell&& cell) const {
  VoronoiMesh mesh;
  in_arena([&] {
    const Frame& frame = frame_;
    // Cells are welded and assembled along a curve through their seeds, not in seed order: the
    // welding and the assembly look at every cell's neighbours, which are then mostly near it in
    // memory, and the cells' data is copied in that order. On igl_bunny's seeds (surface seeds
    // first, then the interior ones) welding and checking took 40 % less time on one thread. The
    // mesh numbers its cells in seed order all the same.
    const std::vector<std::uint32_t> along = geometry::curve_order(
        raw_.size(), [&](std::size_t c) -> const Point& { return frame.normalized[cell_seeds_[c]]; });
    std::vector<RawCell> raw(raw_.size());  // the fallbacks below cut some again, for this mesh only
    std::vector<Index> cell_seeds(raw_.size());
    std::vector<std::int32_t> cell_of_seed(cell_of_seed_.size(), kNoCell);
    tbb::parallel_for(std::size_t{0}, along.size(), [&](std::size_t i) {
      raw[i] = cell(along[i]);
      cell_seeds[i] = cell_seeds_[along[i]];
      cell_of_seed[cell_seeds[i]] = static_cast<std::int32_t>(i);
    });
    // Where cells disagree after welding, nearly cospherical seeds left a vertex split on one side
    // only, or round-off a tiny feature: those cells and their neighbours are cut again, at their
    // local scale and from bigger initial cubes, and their tolerance rises, to 1e-6 of
    // the empty-sphere radius at most. Only theirs: on cgal_bones, three cells that needed 1e-6
    // had it raised for all, and a thousand tiny faces elsewhere turned by up to 5 degrees from
    // their seed links.
    constexpr double kTolerances[] = {1e-9, 1e-9, 1e-8, 1e-7, 1e-6};
    constexpr int kAttempts = static_cast<int>(std::size(kTolerances));
    std::vector<double> tolerance(raw.size(), kTolerances[0]);
    // The cells marked and the cells next to them, in order.
    const auto cells_and_neighbours = [&](const std::vector<char>& marked) {
      const std::vector<char> in = with_neighbours(raw, cell_of_seed, marked);
      std::vector<std::size_t> cells;
      for (std::size_t c = 0; c < raw.size(); ++c) {
        if (in[c]) cells.push_back(c);
      }
      return cells;
    };
    // The seeds' tree, built when a fallback first needs it.
    std::optional<SeedTree> tree;
    const auto seed_tree = [&]() -> const SeedTree& { return tree ? *tree : tree.emplace(frame.normalized); };
    // The cells that fail and their neighbours, cut again for the next attempt.
    const auto cut_again = [&](const std::vector<char>& failed, int attempt) {
      const std::vector<std::size_t> which = cells_and_neighbours(failed);
      for (std::size_t c : which) tolerance[c] = std::max(tolerance[c], kTolerances[attempt + 1]);
      recompute_voronoi_cells(frame.normalized, cell_seeds, which, attempt + 1, raw, &seed_tree());
      return which;
    };
    // Which of the cells `which` and their neighbours still disagree among themselves, welded and
    // assembled alone: a few dozen cells instead of every cell for each attempt. (The assembly of
    // all cells has the last word; this tells when it is worth running, and, before the first,
    // which cells to mend. A cell that disagrees only here, where a neighbour beyond the set
    // would have joined two of its points, is cut again and welded at a higher tolerance: a cost,
    // not an error.)
    const auto disagreeing = [&](const std::vector<std::size_t>& which) {
      std::vector<char> marked(raw.size(), 0);
      for (std::size_t c : which) marked[c] = 1;
      const std::vector<std::size_t> local = cells_and_neighbours(marked);
      std::vector<RawCell> local_raw(local.size());
      std::vector<std::uint32_t> local_number(local.size());  // the scratch mesh's numbers: any
      std::iota(local_number.begin(), local_number.end(), 0u);
      std::vector<Index> local_seeds(local.size());
      std::vector<double> local_tolerance(local.size());
      std::vector<std::int32_t> local_of_seed(cell_of_seed.size(), kNoCell);
      for (std::size_t k = 0; k < local.size(); ++k) {
        local_raw[k] = raw[local[k]];
        local_seeds[k] = cell_seeds[local[k]];
        local_tolerance[k] = tolerance[local[k]];
        local_of_seed[local_seeds[k]] = static_cast<std::int32_t>(k);
      }
      VoronoiMesh scratch;
      bool closed = false;
      const std::vector<char> local_failed =
          weld_and_assemble(seeds_, frame, local_raw, local_seeds, local_of_seed, local_number, local_tolerance, Raw::Keep,
                            scratch, closed);
      std::vector<char> failed(raw.size(), 0);
      for (std::size_t k = 0; k < local.size(); ++k) failed[local[k]] = local_failed[k];
      return failed;
    };
    // Cuts again the cells `failed` marks, and then those of them that still disagree among
    // themselves, for further attempts, before all cells are assembled again.
    const auto mend = [&](const std::vector<char>& failed, int& attempt) {
      std::vector<std::size_t> which = cut_again(failed, attempt);
      while (attempt + 2 < kAttempts) {
        const std::vector<char> still = disagreeing(which);
        if (std::count(still.begin(), still.end(), 1) == 0) break;
        which = cut_again(still, ++attempt);
      }
    };
    // A weld of all cells that fails is thrown away, and it fails wherever two neighbours
    // resolved a degenerate vertex differently (on igl_bunny 4 cells of 282 371; a sixth of the
    // stage went to the weld thrown away). Such a neighbour has an edge near vanishing, so the
    // cells with one, and their neighbours, are welded alone first, and those that disagree there
    // are mended before all cells are welded. Cells this misses (on cgal_bones it finds 46, and
    // the weld of all 8 more, whose disagreement shows only among more cells) go through the
    // fallbacks from the first: the attempts start again, and a cell's tolerance only rises.
    if (const std::vector<std::size_t> suspects = near_degenerate(raw); !suspects.empty()) {
      const std::vector<char> failed = disagreeing(suspects);
      if (std::count(failed.begin(), failed.end(), 1) > 0) {
        int attempt = 0;
        mend(failed, attempt);
      }
    }
    for (int attempt = 0;; ++attempt) {
      bool closed = false;
      const std::vector<char> failed =
          weld_and_assemble(seeds_, frame, raw, cell_seeds, cell_of_seed, along, tolerance, Raw::Release, mesh, closed);
      if (std::count(failed.begin(), failed.end(), 1) == 0) break;
      if (attempt == kAttempts - 1) {
        fail_on_lowest(failed, cell_seeds, closed ? "and a neighbour see their common face differently after welding"
                                                  : "is not closed after welding its degenerate vertices");
      }
      mend(failed, attempt);
    }
    cells::renumber_points(mesh);
    geometry::measure_cells(mesh);
  });
  return mesh;
}

}  // namespace cells

VoronoiMesh compute_cells(const std::vector<Seed>& seeds, const CellsOptions& options) {
  VoronoiMesh mesh = cells::GrowingCells(seeds, options).mesh();
  release_free_memory();  // as conforming_cells does
  return mesh;
}

std::size_t count_interior_faces(const VoronoiMesh& mesh) {
  return static_cast<std::size_t>(
      std::count_if(mesh.faces.begin(), mesh.faces.end(), [](const VoronoiFace& f) { return f.neighbour != kNoCell; }));
}

std::size_t count_interface_faces(const VoronoiMesh& mesh) {
  return static_cast<std::size_t>(std::count_if(mesh.faces.begin(), mesh.faces.end(), [&](const VoronoiFace& f) {
    return f.neighbour != kNoCell && mesh.cells[f.owner].region != mesh.cells[f.neighbour].region;
  }));
}

FaceGeometry face_geometry(const VoronoiMesh& mesh, std::size_t face) {
  const std::vector<Index>& polygon = mesh.faces[face].points;
  return geometry::polygon_geometry(polygon.size(), [&](std::size_t k) -> const Point& { return mesh.points[polygon[k]]; });
}

std::string region_name(const VoronoiMesh& mesh, std::int32_t label) {
  if (label >= 0 && static_cast<std::size_t>(label) < mesh.region_names.size()) return mesh.region_names[label];
  return label == kOutsideRegion ? "outside" : "material" + std::to_string(label);
}

double total_volume(const VoronoiMesh& mesh) {
  double volume = 0;
  for (const VoronoiCell& c : mesh.cells) volume += c.volume;
  return volume;
}

}  // namespace vorocrust
