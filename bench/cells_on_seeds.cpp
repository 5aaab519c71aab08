// The cells stage on a run's own seeds (OUTDIR/seeds.csv) against Voro++ by itself on the same
// seeds (voropp_full_cells.hpp: one container, one thread, full cells extracted), at Voro++'s
// own block size times each factor given, since VoroCrust's seeds (thin layers of surface seeds, sparse interior and outside seeds) are far from the even
// density that block size assumes; then compute_cells, the whole conforming mesh, on 1 and 2
// threads. Prints one line per measurement; the figures go to bench/RESULTS.md.
//
// Usage: vorocrust_bench_cells_on_seeds SEEDS.csv [BLOCK_FACTOR...]   (default factors 1 2 3 4 5 6)
#include <voro++.hh>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "vorocrust/cells.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/seeds.hpp"
#include "voropp_full_cells.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Voro++'s single-thread rate over the seeds' bounding box: the cells it gives and the seconds,
// container filling included.
std::pair<std::size_t, double> voropp_cells(const std::vector<vorocrust::Seed>& seeds, double block_factor) {
  Eigen::AlignedBox3d box;
  for (const vorocrust::Seed& s : seeds) box.extend(s.position);
  const vorocrust::Point margin = 1e-3 * box.sizes();
  const vorocrust::Point lo = box.min() - margin, hi = box.max() + margin, size = hi - lo;
  const double block = std::cbrt(size.prod() * voro::optimal_particles / static_cast<double>(seeds.size()));
  std::array<int, 3> blocks{};
  for (int d = 0; d < 3; ++d) blocks[d] = std::max(1, static_cast<int>(std::ceil(block_factor * size[d] / block)));

  const Clock::time_point start = Clock::now();
  const std::size_t cells = vorocrust::bench::voropp_full_cells(seeds, lo, hi, blocks);
  return {cells, seconds_since(start)};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s SEEDS.csv [BLOCK_FACTOR...]\n", argv[0]);
    return 2;
  }
  std::vector<double> factors;
  for (int k = 2; k < argc; ++k) factors.push_back(std::stod(argv[k]));
  if (factors.empty()) factors = {1, 2, 3, 4, 5, 6};
  try {
    const std::vector<vorocrust::Seed> seeds = vorocrust::read_seeds_csv(argv[1]);
    const auto materials = static_cast<std::size_t>(
        std::count_if(seeds.begin(), seeds.end(), [](const vorocrust::Seed& s) { return s.region > 0; }));
    std::printf("%s: %zu seeds, %zu with a material\n", argv[1], seeds.size(), materials);
    for (const double factor : factors) {
      const auto [cells, time] = voropp_cells(seeds, factor);
      std::printf("Voro++ container, blocks x%g per axis, 1 thread: %zu cells in %.2f s, %.1f k cells/s\n", factor, cells,
                  time, static_cast<double>(cells) / time / 1e3);
    }
    for (const int threads : {1, 2}) {
      vorocrust::CellsOptions options;
      options.threads = threads;
      const Clock::time_point start = Clock::now();
      const std::size_t cells = vorocrust::compute_cells(seeds, options).cells.size();
      const double time = seconds_since(start);
      std::printf("compute_cells (cut, weld, assemble), %d thread%s: %zu cells in %.2f s, %.1f k cells/s\n", threads,
                  threads > 1 ? "s" : "", cells, time, static_cast<double>(cells) / time / 1e3);
    }
  } catch (const vorocrust::Error& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 3;
  }
  return 0;
}
