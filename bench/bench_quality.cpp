// Surface quality (paper section 3): measure_surface_quality of a model against itself, on one
// thread and on all, at the model's own size and after one 1-to-4 split of every triangle (past
// 100 000 triangles). Results go to bench/RESULTS.md.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <string>
#include <utility>

#include "vorocrust/vorocrust.hpp"

namespace {

const char* const kModels[] = {"heptoroid_welded.off", "ajc_rocker-arm.obj"};

// Every triangle cut into four through its edge midpoints: the same surface, four times the faces.
vorocrust::SurfaceMesh split_in_four(const vorocrust::SurfaceMesh& in) {
  using vorocrust::Index;
  vorocrust::SurfaceMesh out;
  out.groups = in.groups;
  out.vertices = in.vertices;
  std::map<std::pair<Index, Index>, Index> midpoints;
  const auto midpoint = [&](Index a, Index b) {
    const auto [it, added] = midpoints.try_emplace(std::minmax(a, b), static_cast<Index>(out.vertices.size()));
    if (added) out.vertices.push_back(0.5 * (in.vertices[a] + in.vertices[b]));
    return it->second;
  };
  for (std::size_t f = 0; f < in.num_faces(); ++f) {
    const auto [a, b, c] = in.triangles[f];
    const Index ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
    for (const vorocrust::Triangle& t : {vorocrust::Triangle{a, ab, ca}, {ab, b, bc}, {ca, bc, c}, {ab, bc, ca}})
      out.add_triangle(t, in.face_group[f]);
  }
  return out;
}

void quality(benchmark::State& state) {
  const auto path = std::filesystem::path(VOROCRUST_MODELS_DIR) / kModels[state.range(0)];
  const bool split = state.range(1) != 0;
  const int threads = static_cast<int>(state.range(2));
  vorocrust::SurfaceMesh mesh = vorocrust::read_mesh(path);
  if (split) mesh = split_in_four(mesh);
  state.SetLabel(path.filename().string() + (split ? " split in four" : "") +
                 (threads == 1 ? ", 1 thread" : ", all threads"));
  const vorocrust::ThreadLimit limit(threads);
  vorocrust::SurfaceQuality q;
  for (auto _ : state) q = vorocrust::measure_surface_quality(mesh, mesh);
  state.counters["triangles"] = static_cast<double>(q.triangles);
  state.counters["samples"] = static_cast<double>(q.input_samples + q.output_samples);
  state.counters["samples/s"] =
      benchmark::Counter(static_cast<double>(q.input_samples + q.output_samples), benchmark::Counter::kIsIterationInvariantRate);
}

BENCHMARK(quality)->ArgsProduct({{0, 1}, {0, 1}, {1, 0}})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
