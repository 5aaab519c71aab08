// Interior seeds (paper 2.5, A.5) through the whole pipeline on cgal_joint.off: no seed enters a
// protecting ball or a surface seed's ball, so the surface survives in the cells; the sampled
// seeds keep clear of the balls' spheres, the cap seeds lie on them; radii stay L-Lipschitz;
// every mode gives cells bounded by exactly the output surface, with no highly skew face.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <map>
#include <numeric>

#include "cells/mesh_checks.hpp"
#include "core/surface_measures.hpp"
#include "interior/sample_interior.hpp"
#include "test_support.hpp"
#include "vorocrust/face_skewness.hpp"
#include "vorocrust/mesher.hpp"
#include "vorocrust/read_mesh.hpp"

namespace vorocrust {
namespace {

const SurfaceMesh& joint() {
  static const SurfaceMesh mesh = read_mesh(test::model("cgal_joint.off"));
  return mesh;
}

// One run per mode, shared by the tests.
const MeshResult& run(InteriorMode mode) {
  static std::map<InteriorMode, MeshResult> runs;
  auto it = runs.find(mode);
  if (it == runs.end()) {
    MeshOptions options;
    options.interior = mode;
    options.cvt_iterations = 5;
    options.seed = 3;
    it = runs.emplace(mode, generate_mesh(joint(), options)).first;
  }
  return it->second;
}

std::size_t first_interior(const MeshResult& r) {
  const auto it = std::find_if(r.seeds.begin(), r.seeds.end(), [](const Seed& s) { return s.kind != SeedKind::Surface; });
  return static_cast<std::size_t>(it - r.seeds.begin());
}

void expect_surface_untouched(const MeshResult& r) {
  const std::size_t first = first_interior(r);
  ASSERT_LT(first, r.seeds.size());
  for (std::size_t i = first; i < r.seeds.size(); ++i) {
    const Point& z = r.seeds[i].position;
    ASSERT_NE(r.seeds[i].kind, SeedKind::Surface) << i;
    EXPECT_EQ(r.seeds[i].kind == SeedKind::Outside, r.seeds[i].region == kOutsideRegion) << i;
    bool on_a_sphere = false;
    for (const Ball& b : r.balls) {
      const double d = (z - b.center).norm();
      ASSERT_GE(d, b.radius * (1 - 1e-12)) << "seed " << i << " inside a protecting ball";
      on_a_sphere = on_a_sphere || d <= b.radius * (1 + 1e-12);
      if (r.seeds[i].kind != SeedKind::Cap && r.seeds[i].kind != SeedKind::Repair) {
        ASSERT_GE(d, b.radius * (1 + kBallClearance)) << "seed " << i << " within the clearance of a ball";
      }
    }
    if (r.seeds[i].kind == SeedKind::Cap) {
      EXPECT_TRUE(on_a_sphere) << "cap seed " << i << " on no ball's sphere";
      continue;
    }
    if (r.seeds[i].kind == SeedKind::Repair) continue;  // placed, split off a cell: outside the balls only
    for (std::size_t s = 0; s < first; ++s) {
      ASSERT_GE((z - r.seeds[s].position).norm(), r.seeds[s].radius) << "seed " << i << " inside surface seed " << s;
    }
  }
}

// The material cells' boundary is the output surface: one face per triangle, the same enclosed
// volume, every face between the inside and the outside.
void expect_bounded_by_the_surface(const MeshResult& r) {
  test::expect_closed_and_convex(r.cells, 1e-9);
  std::size_t boundary = 0;
  for (const VoronoiFace& f : r.cells.faces) {
    if (f.neighbour != kNoCell) continue;
    ++boundary;
    EXPECT_EQ(f.regions, (RegionPair{kInsideRegion, kOutsideRegion}));
  }
  EXPECT_EQ(boundary, r.surface.num_faces());
  std::vector<Index> all(r.surface.num_faces());
  std::iota(all.begin(), all.end(), Index{0});
  const double enclosed = enclosed_volume(r.surface, all);
  EXPECT_NEAR(total_volume(r.cells), enclosed, 1e-9 * enclosed);
  std::size_t material = 0;
  for (const Seed& s : r.seeds) material += s.region != kOutsideRegion;
  EXPECT_EQ(r.cells.cells.size(), material);
  EXPECT_TRUE(skew_faces(r.cells).empty()) << skew_faces(r.cells).size() << " highly skew faces";
}

TEST(SampleInterior, RandomSeedsStayOutOfEveryBallAndKeepTheSurface) {
  const MeshResult& r = run(InteriorMode::Random);
  EXPECT_GT(r.interior.interior_seeds, 100u);
  EXPECT_GT(r.interior.outside_seeds, 100u);
  EXPECT_GT(r.interior.cap_seeds, 100u);
  EXPECT_EQ(r.interior.interior_seeds + r.interior.outside_seeds + r.interior.cap_seeds + r.interior.split_seeds,
            r.seeds.size() - first_interior(r));
  EXPECT_LE(r.interior.split_seeds, r.interior.repair_seeds);
  expect_surface_untouched(r);
  expect_bounded_by_the_surface(r);
}

TEST(SampleInterior, RadiiAreLipschitzAndSeedsOutsideEachOthersBalls) {
  const MeshResult& r = run(InteriorMode::Random);
  const double L = MeshOptions{}.lipschitz;
  for (std::size_t i = first_interior(r); i < r.seeds.size(); ++i) {
    const auto placed = [&](std::size_t k) { return r.seeds[k].kind == SeedKind::Cap || r.seeds[k].kind == SeedKind::Repair; };
    if (placed(i)) continue;  // on spheres or splitting cells, not sampled
    for (std::size_t j = 0; j < r.seeds.size(); ++j) {
      if (i == j || placed(j)) continue;
      const double d = (r.seeds[i].position - r.seeds[j].position).norm();
      ASSERT_LE(r.seeds[i].radius, r.seeds[j].radius + L * d + 1e-12) << i << " " << j;
      if (j < i && r.seeds[j].kind != SeedKind::Surface) {
        // The later seed was placed outside the earlier one's ball (as it was then: radii only shrink).
        ASSERT_GE(d, r.seeds[j].radius) << i << " " << j;
      }
    }
  }
}

// max_size bounds the cells, so the seeds of the materials; the outside seeds only close the
// boundary cells and grow at the Lipschitz rate. Filling the box around the input at max_size made
// 38 outside seeds for every interior one on the unit box at 0.08.
TEST(SampleInterior, MaxSizeBoundsTheMaterialsNotTheOutside) {
  MeshOptions options;
  options.max_size = 0.08;
  const MeshResult r = generate_mesh(read_mesh(test::model("sandia_OneBox.obj")), options);
  ASSERT_GT(r.interior.interior_seeds, 500u);
  EXPECT_LT(r.interior.outside_seeds, 8 * r.interior.interior_seeds);
  double largest_outside = 0;
  for (const Seed& s : r.seeds) {
    if (s.kind == SeedKind::Interior) {
      ASSERT_LE(s.radius, options.max_size);
    }
    if (s.kind == SeedKind::Outside) largest_outside = std::max(largest_outside, s.radius);
  }
  EXPECT_GT(largest_outside, 4 * options.max_size);
  for (const VoronoiCell& cell : r.cells.cells) ASSERT_GT(cell.volume, 0);
}

// The spokes run side by side in batches that do not depend on the thread count: one thread
// gives the seeds that all cores gave. options.threads alone holds the run to one thread, with
// no ThreadLimit (a program linking the library may have none).
TEST(SampleInterior, SameSeedSameSeedsOnOneThread) {
  MeshOptions options;
  options.seed = 3;
  options.threads = 1;
  int most_threads = 0;
  const MeshResult again = generate_mesh(joint(), options, [&](const ProgressUpdate&) {
    most_threads = std::max(most_threads, tbb::this_task_arena::max_concurrency());
    return true;
  });
  EXPECT_EQ(most_threads, 1);
  const MeshResult& r = run(InteriorMode::Random);
  ASSERT_GT(r.interior.spoke_seeds, 0u);
  ASSERT_EQ(again.seeds.size(), r.seeds.size());
  for (std::size_t i = 0; i < r.seeds.size(); ++i) {
    ASSERT_EQ(again.seeds[i].position, r.seeds[i].position) << i;
    ASSERT_EQ(again.seeds[i].radius, r.seeds[i].radius) << i;
  }
  EXPECT_EQ(again.cells.points.size(), r.cells.points.size());
}

TEST(SampleInterior, LatticeGivesCubesInTheDeepInterior) {
  const MeshResult& r = run(InteriorMode::Lattice);
  EXPECT_GT(r.interior.lattice_seeds, 20u);
  expect_surface_untouched(r);
  expect_bounded_by_the_surface(r);
  // A lattice seed whose six lattice neighbours are seeds too, and no seed of the random layer
  // near the surface close enough to cut a corner, has a cube for its cell. The joint is thin,
  // and the poles on the balls' spheres (cap seeds) make a second layer under the surface: about
  // one lattice seed in twenty-five is that deep (fewer poles leave room for more lattice seeds
  // near the surface, none of them a cube: 29 cubes of 552 lattice seeds, then 27 of 686).
  std::size_t cubes = 0;
  for (const VoronoiCell& c : r.cells.cells) {
    if (c.faces.size() != 6) continue;
    double lo = 1e300, hi = 0;
    for (Index f : c.faces) {
      const double a = test::area_vector(r.cells, r.cells.faces[f].points).norm();
      lo = std::min(lo, a);
      hi = std::max(hi, a);
    }
    cubes += hi < lo * (1 + 1e-6);
  }
  EXPECT_GT(cubes, r.interior.lattice_seeds / 30);
}

TEST(SampleInterior, CvtMovesInteriorSeedsTowardTheirCentroidsAndKeepsTheSurface) {
  const MeshResult& random = run(InteriorMode::Random);
  const MeshResult& cvt = run(InteriorMode::Cvt);
  expect_surface_untouched(cvt);
  expect_bounded_by_the_surface(cvt);
  // Equal up to the skew repairs and the splits of long cells, which follow the cells and so
  // differ.
  const auto added_after = [](const MeshResult& r) { return r.interior.repair_seeds + r.interior.aspect_split_seeds; };
  const std::size_t sampled = cvt.seeds.size() - added_after(cvt);
  ASSERT_EQ(sampled, random.seeds.size() - added_after(random));
  std::size_t moved = 0;
  for (std::size_t i = 0; i < sampled; ++i) {
    if (random.seeds[i].kind == SeedKind::Interior) {
      moved += cvt.seeds[i].position != random.seeds[i].position;
    } else {
      ASSERT_EQ(cvt.seeds[i].position, random.seeds[i].position) << "seed " << i << " is no interior seed";
    }
  }
  EXPECT_GT(moved, random.interior.interior_seeds / 2);
  // The CVT energy's proxy: the distance of interior seeds from their cells' centroids, over the
  // seeds free to reach them (a seed bounding a surface seed's cell keeps its depth).
  const auto off_centre = [](const MeshResult& r) {
    double sum = 0;
    for (const VoronoiCell& c : r.cells.cells) {
      if (r.seeds[c.seed].kind != SeedKind::Interior) continue;
      const bool next_to_surface = std::any_of(c.faces.begin(), c.faces.end(), [&](Index f) {
        const VoronoiFace& face = r.cells.faces[f];
        return r.seeds[face.owner_seed].kind == SeedKind::Surface || r.seeds[face.neighbour_seed].kind == SeedKind::Surface;
      });
      if (!next_to_surface) sum += (r.seeds[c.seed].position - c.centroid).norm();
    }
    return sum;
  };
  EXPECT_LT(off_centre(cvt), 0.75 * off_centre(random));
  // And what users look for: rounder cells, the surface cells included.
  ASSERT_TRUE(cvt.cell_quality && random.cell_quality);
  EXPECT_LT(cvt.cell_quality->mean_aspect_ratio, random.cell_quality->mean_aspect_ratio);
}

}  // namespace
}  // namespace vorocrust
