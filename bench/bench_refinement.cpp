// Refinement (paper 2.3) per model, one thread and all threads: balls per second and the
// Table 1 rows (corner protection, edge protection, surface coverage, C3 fixing, C1/C2 sweep).
// Results go to bench/RESULTS.md.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "vorocrust/vorocrust.hpp"

namespace {

const char* const kModels[] = {"sandia_bracket.obj", "cgal_fandisk.off", "cgal_joint.off", "netgen_hinge.stl",
                               "sandia_bird.obj", "sandia_non_manifold_box.obj"};

void refine(benchmark::State& state) {
  const auto path = std::filesystem::path(VOROCRUST_MODELS_DIR) / kModels[state.range(0)];
  const int threads = static_cast<int>(state.range(1));
  state.SetLabel(path.filename().string() + (threads == 1 ? " 1 thread" : " all threads"));
  vorocrust::SurfaceMesh mesh = vorocrust::read_mesh(path);
  (void)vorocrust::validate(mesh);
  vorocrust::MeshOptions options;
  options.stop_after = vorocrust::Stage::Balls;
  options.threads = threads;
  const vorocrust::ThreadLimit limit(threads);
  vorocrust::MeshResult result;
  for (auto _ : state) result = vorocrust::generate_mesh(mesh, options);
  const auto& r = result.refinement;
  const double balls = static_cast<double>(r.balls[0] + r.balls[1] + r.balls[2]);
  state.counters["balls"] = balls;
  state.counters["corner"] = static_cast<double>(r.balls[0]);
  state.counters["crease"] = static_cast<double>(r.balls[1]);
  state.counters["patch"] = static_cast<double>(r.balls[2]);
  state.counters["balls/s"] = benchmark::Counter(balls, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["t_samples"] = r.setup_seconds;
  state.counters["t_corner"] = r.phase_seconds[0];
  state.counters["t_edge"] = r.phase_seconds[1];
  state.counters["t_surface"] = r.phase_seconds[2];
  state.counters["t_c3"] = r.c3_seconds;
  state.counters["t_sweep"] = r.sweep_seconds;
}

BENCHMARK(refine)->ArgsProduct({{0, 1, 2, 3, 4, 5}, {1, 0}})->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
