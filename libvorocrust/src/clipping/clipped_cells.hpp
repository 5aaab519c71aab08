// Internal: the clipped methods end to end, from a labelled domain to its clipped Voronoi mesh.
//
// Contract of clipped_cells(domain, options, phases): every region of `domain` but the outside
// (label 0) is a material, meshed with seeds of its own.
// - seeds: options.given where there are any (sorted by material, their order kept within
//   each); else first Ebeida and Mitchell's seeds on each material's reflex sharp edges
//   (edge_seeds.hpp: r / sqrt(2) apart, kind Surface, never moved), then InteriorMode::Random
//   gives their maximal Poisson-disk seeds at options.radius in each material (poisson_disk_seeds.hpp, phase "interior seeds"); Lattice a
//   cubic lattice of that spacing, the points inside the materials, each moved by up to a
//   thousandth of the spacing (ties of a perfect lattice are not decided), and Poisson-disk
//   seeds where it leaves room (a thin part between its points); Cvt the Poisson-disk seeds (or
//   the given ones) moved by options.cvt_iterations Lloyd iterations on the clipped cells (Yan et
//   al. 2011, section 5.2: each seed to its clipped cell's centroid; a centroid outside the
//   material leaves its seed where it was, and seeds of a kind other than Interior, given seeds
//   on the surface, stay; phase "cvt"). After the first half of the iterations (rounded up), the
//   seeds of the cells on the surface (a face toward no cell or another material) become kind
//   Surface and move to the point of their material's boundary nearest their centroid, a
//   thousandth of the radius inside, for the rest: Yan et al.'s constrained phase, which puts
//   seeds on the surface so that the dual tetrahedra reach it.
// - with options.sliver_angle > 0, Yan et al.'s post-processing: in rounds, a seed of each dual
//   tetrahedron (dual_tets.hpp) whose smallest dihedral angle is below it tries small random
//   moves, up to 16, and keeps the first whose new tetrahedra are better than those it removes,
//   judged from the Voronoi cells of the seed and its neighbours (local_stars.hpp; a tetrahedron
//   counts as changed when a seed of it moved). Interior seeds move, and those the constrained
//   phase holds, which slide along the surface (phase "sliver perturbation"). It stops when no
//   tetrahedron is below the angle, when three rounds running keep no move, or after 30 rounds;
//   what it did is in the stats' `slivers`.
// - then each material's Voronoi cells of its seeds and outside seeds 1.5 radii beyond the
//   domain's box (phase "cells"), cut to the materials (clip_cells.hpp; phase "clipping"). Where
//   an outside seed is nearer part of the surface than every material seed, the outside seeds
//   move fourfold farther and the cells are cut again.
// Returns the seeds (the cells' first, in cell order, grouped by material, then the outside seeds)
// and the mesh.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "clipping/clip_cells.hpp"
#include "core/phases.hpp"
#include "vorocrust/modes.hpp"
#include "vorocrust/seeds.hpp"

namespace vorocrust::clipping {

struct ClippedOptions {
  double radius = 0;  // the seeds' Poisson-disk radius, or the lattice's spacing
  InteriorMode mode = InteriorMode::Random;
  int cvt_iterations = 20;
  // Dual tetrahedra with a dihedral angle below this many degrees have their seeds perturbed; 0: none.
  double sliver_angle = 0;
  // Reflex edges whose faces' normals turn by more than this take seeds (edge_seeds.hpp).
  double sharp_angle_degrees = 30;
  std::uint64_t seed = 0;
  int threads = 0;
  // Seeds given instead of sampled (each inside its material; each moved by a thousandth of the
  // distance to its nearest, as the lattice is; `mode` Cvt still moves them).
  std::vector<Seed> given;
  // Called with the material seeds before their cells, to refuse a run that would not fit.
  std::function<void(const std::vector<Seed>&)> before_cells;
};

struct ClippedMesh {
  std::vector<Seed> seeds;
  VoronoiMesh cells;
  ClippingStats stats;
};

ClippedMesh clipped_cells(const SurfaceMesh& domain, const ClippedOptions& options, Phases& phases);

}  // namespace vorocrust::clipping
