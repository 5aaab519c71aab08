// Input stage timings: reading each format, validation (with and without the self-intersection
// search) and the connectivity summary, on the shared models. Results go to bench/RESULTS.md.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "vorocrust/vorocrust.hpp"

namespace {

std::filesystem::path model(const std::string& name) { return std::filesystem::path(VOROCRUST_MODELS_DIR) / name; }

const char* const kModels[] = {"heptoroid_welded.off", "ajc_rocker-arm.obj", "netgen_hinge.stl", "igl_bunny.off"};

void read(benchmark::State& state) {
  const auto path = model(kModels[state.range(0)]);
  state.SetLabel(path.filename().string());
  std::size_t faces = 0;
  for (auto _ : state) faces = vorocrust::read_mesh(path).num_faces();
  state.counters["faces"] = static_cast<double>(faces);
  state.counters["faces/s"] = benchmark::Counter(static_cast<double>(faces), benchmark::Counter::kIsIterationInvariantRate);
}

void validate(benchmark::State& state) {
  const auto path = model(kModels[state.range(0)]);
  state.SetLabel(path.filename().string() + (state.range(1) ? " +self-intersections" : ""));
  const vorocrust::SurfaceMesh original = vorocrust::read_mesh(path);
  vorocrust::ValidationOptions options;
  options.check_self_intersections = state.range(1) != 0;
  for (auto _ : state) {
    vorocrust::SurfaceMesh mesh = original;
    benchmark::DoNotOptimize(vorocrust::validate(mesh, options));
  }
  state.counters["faces"] = static_cast<double>(original.num_faces());
}

void info(benchmark::State& state) {
  const auto path = model(kModels[state.range(0)]);
  state.SetLabel(path.filename().string());
  const vorocrust::SurfaceMesh mesh = vorocrust::read_mesh(path);
  for (auto _ : state) benchmark::DoNotOptimize(vorocrust::mesh_info(mesh));
}

BENCHMARK(read)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);
BENCHMARK(validate)->ArgsProduct({{0, 1, 3}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK(info)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
