// The surface stage on a real sharp model (paper 2.4): no half-covered seed pair left, the
// input's topology, every corner a vertex and every crease a chain of edges, regions on the
// right sides, reproducible.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "core/surface_measures.hpp"
#include "test_support.hpp"
#include "vorocrust/mesh_info.hpp"
#include "vorocrust/mesher.hpp"
#include "vorocrust/read_mesh.hpp"
#include "vorocrust/validate.hpp"

namespace vorocrust {
namespace {

struct Run {
  SurfaceMesh input;
  MeshResult result;
};

const Run& joint_run() {
  static const Run run = [] {
    Run r;
    r.input = read_mesh(test::model("cgal_joint.off"));
    (void)validate(r.input);
    MeshOptions options;
    options.stop_after = Stage::Surface;
    r.result = generate_mesh(r.input, options);
    return r;
  }();
  return run;
}

TEST(SurfaceSeeds, NoHalfCoveredSeedPairIsLeft) {
  const SliverStats& s = joint_run().result.slivers;
  ASSERT_FALSE(s.iterations.empty());
  EXPECT_EQ(s.iterations.back().half_covered, 0u);
  EXPECT_GT(s.iterations.front().half_covered, 0u) << "the model has slivers to begin with";
  EXPECT_FALSE(s.safe_mode);
}

TEST(SurfaceSeeds, TheSurfaceHasTheInputsTopology) {
  const MeshInfo in = mesh_info(joint_run().input), out = mesh_info(joint_run().result.surface);
  EXPECT_EQ(out.components.size(), in.components.size());
  EXPECT_EQ(out.boundary_edges, 0u);
  EXPECT_EQ(out.non_manifold_edges, 0u);
  ASSERT_TRUE(in.genus && out.genus);
  EXPECT_EQ(*out.genus, *in.genus);
}

TEST(SurfaceSeeds, CornersAreVerticesAndCreasesAreChainsOfEdges) {
  const MeshResult& r = joint_run().result;
  std::map<std::tuple<double, double, double>, const Ball*> ball_at;
  for (const Ball& b : r.balls) ball_at[{b.center.x(), b.center.y(), b.center.z()}] = &b;
  std::vector<const Ball*> ball_of(r.surface.num_vertices());
  for (std::size_t v = 0; v < ball_of.size(); ++v) {
    const Point& p = r.surface.vertices[v];
    auto it = ball_at.find({p.x(), p.y(), p.z()});
    ASSERT_NE(it, ball_at.end()) << "surface vertex " << v << " is not a ball centre";
    ball_of[v] = it->second;
  }
  std::size_t corner_vertices = 0;
  for (const Ball* b : ball_of) corner_vertices += b->type == StratumType::Corner;
  EXPECT_EQ(corner_vertices, r.refinement.balls[0]) << "every corner ball's centre is a surface vertex";

  // Along a crease, each crease ball is joined to exactly two balls of the same crease or to
  // corners: the crease appears as a chain of surface edges.
  std::set<std::pair<Index, Index>> edges;
  for (const Triangle& t : r.surface.triangles) {
    for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
  }
  std::vector<int> chain_degree(ball_of.size(), 0);
  for (const auto& [a, b] : edges) {
    const Ball &ba = *ball_of[a], &bb = *ball_of[b];
    const auto along = [](const Ball& crease, const Ball& other) {
      return crease.type == StratumType::Crease &&
             (other.type == StratumType::Corner || (other.type == StratumType::Crease && other.stratum == crease.stratum));
    };
    if (along(ba, bb)) ++chain_degree[a];
    if (along(bb, ba)) ++chain_degree[b];
  }
  std::size_t crease_vertices = 0, off_chain = 0;
  for (std::size_t v = 0; v < ball_of.size(); ++v) {
    if (ball_of[v]->type != StratumType::Crease) continue;
    ++crease_vertices;
    off_chain += chain_degree[v] != 2;
  }
  EXPECT_EQ(crease_vertices, r.refinement.balls[1]);
  EXPECT_EQ(off_chain, 0u) << "crease balls not joined to exactly two neighbours along their crease";
}

TEST(SurfaceSeeds, RegionsAreOnTheRightSides) {
  const MeshResult& r = joint_run().result;
  ASSERT_EQ(r.surface.face_regions.size(), r.surface.num_faces());
  for (const RegionPair& regions : r.surface.face_regions) {
    ASSERT_EQ(regions.back, kInsideRegion);
    ASSERT_EQ(regions.front, kOutsideRegion);
  }
  // Normals point out, and the enclosed volume is the input's within the approximation.
  const auto volume = [](const SurfaceMesh& mesh) {
    std::vector<Index> all(mesh.num_faces());
    for (Index f = 0; f < all.size(); ++f) all[f] = f;
    return enclosed_volume(mesh, all);
  };
  const double in = volume(joint_run().input), out = volume(r.surface);
  EXPECT_GT(out, 0);
  EXPECT_NEAR(out / in, 1.0, 0.02);
  // Each pair of seeds straddles its facet: one inside, one outside.
  std::size_t surface_seeds = 0;
  for (const Seed& s : r.seeds) surface_seeds += s.kind == SeedKind::Surface;
  EXPECT_EQ(surface_seeds, 2 * r.surface.num_faces());
}

TEST(SurfaceSeeds, RunsAreReproducible) {
  MeshOptions options;
  options.stop_after = Stage::Surface;
  options.threads = 1;
  const MeshResult again = generate_mesh(joint_run().input, options);
  EXPECT_EQ(again.surface.vertices, joint_run().result.surface.vertices);
  EXPECT_EQ(again.surface.triangles, joint_run().result.surface.triangles);
  ASSERT_EQ(again.seeds.size(), joint_run().result.seeds.size());
  for (std::size_t i = 0; i < again.seeds.size(); ++i) ASSERT_EQ(again.seeds[i].position, joint_run().result.seeds[i].position);
}

}  // namespace
}  // namespace vorocrust
