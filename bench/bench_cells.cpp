// The cells stage: compute_cells on a jittered cubic lattice of 48^3 = 110 592 seeds whose outer
// layer is outside (97 336 cells), on 1 and 2 threads, against Voro++'s own single-thread rate
// for the same full cells (vertices, faces and neighbours extracted) from one container of all
// the seeds, and the raw slab computation alone; then measure_cell_quality on those cells.
// Results go to bench/RESULTS.md.
#include <benchmark/benchmark.h>

#include <tbb/task_arena.h>

#include <cmath>
#include <voro++.hh>

#include "cells/seed_sets.hpp"
#include "cells/voronoi_cells.hpp"
#include "vorocrust/cell_quality.hpp"
#include "vorocrust/cells.hpp"
#include "voropp_full_cells.hpp"

namespace {

using vorocrust::Seed;

constexpr int kSide = 48;

const std::vector<Seed>& seeds() {
  static const std::vector<Seed> s = vorocrust::test::lattice_seeds(kSide, 0.3, [](const vorocrust::Point& p) {
    const bool outer = (p.array() < 0.5).any() || (p.array() > kSide - 1.5).any();
    return outer ? vorocrust::kOutsideRegion : vorocrust::kInsideRegion;
  });
  return s;
}

std::size_t material_count() {
  std::size_t n = 0;
  for (const Seed& s : seeds()) n += s.region > 0;
  return n;
}

void compute_cells(benchmark::State& state) {
  vorocrust::CellsOptions options;
  options.threads = static_cast<int>(state.range(0));
  std::size_t cells = 0;
  for (auto _ : state) cells = vorocrust::compute_cells(seeds(), options).cells.size();
  state.counters["cells"] = static_cast<double>(cells);
  state.counters["cells/s"] = benchmark::Counter(static_cast<double>(cells), benchmark::Counter::kIsIterationInvariantRate);
}

// The Voro++ part of compute_cells alone: each cell cut nearest first, before welding and assembly.
void raw_cells(benchmark::State& state) {
  std::vector<vorocrust::Point> positions;
  std::vector<vorocrust::Index> cell_seeds;
  for (std::size_t s = 0; s < seeds().size(); ++s) {
    positions.push_back(seeds()[s].position);
    if (seeds()[s].region > 0) cell_seeds.push_back(static_cast<vorocrust::Index>(s));
  }
  tbb::task_arena arena(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    arena.execute([&] { benchmark::DoNotOptimize(vorocrust::cells::compute_voronoi_cells(positions, cell_seeds)); });
  }
  state.counters["cells/s"] =
      benchmark::Counter(static_cast<double>(cell_seeds.size()), benchmark::Counter::kIsIterationInvariantRate);
}

// Voro++ by itself, one thread: one container of every seed, Voro++'s own block size, each
// material cell computed with its neighbours and its vertices, faces and neighbour ids extracted.
void voropp_full_cells(benchmark::State& state) {
  const double lo = -1, hi = kSide;
  const int blocks = static_cast<int>(std::lround((hi - lo) / std::cbrt(voro::optimal_particles)));
  std::size_t cells = 0;
  for (auto _ : state) {
    cells = vorocrust::bench::voropp_full_cells(seeds(), vorocrust::Point::Constant(lo), vorocrust::Point::Constant(hi),
                                                {blocks, blocks, blocks});
  }
  state.counters["cells"] = static_cast<double>(cells);
  state.counters["cells/s"] = benchmark::Counter(static_cast<double>(cells), benchmark::Counter::kIsIterationInvariantRate);
}

// The volume quality of the cells above: per cell the smallest enclosing sphere and the largest
// inscribed ball, then the figures over all cells.
void measure_cell_quality(benchmark::State& state) {
  static const vorocrust::VoronoiMesh mesh = vorocrust::compute_cells(seeds());
  vorocrust::CellQualityOptions options;
  options.threads = static_cast<int>(state.range(0));
  double worst = 0;
  for (auto _ : state) worst = vorocrust::measure_cell_quality(mesh, options).max_aspect_ratio;
  state.counters["max aspect ratio"] = worst;
  state.counters["cells/s"] =
      benchmark::Counter(static_cast<double>(mesh.cells.size()), benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

BENCHMARK(voropp_full_cells)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(raw_cells)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();
BENCHMARK(compute_cells)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();
BENCHMARK(measure_cell_quality)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (material_count() == 0) return 1;
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
