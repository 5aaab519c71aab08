// sharp_bends: which shared models look like scans to the sharp-edge rule at the default sharp
// angle (30 degrees), and which are CAD parts whose sharp edges are true creases.
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "features/scan_likeness.hpp"
#include "test_support.hpp"
#include "vorocrust/read_mesh.hpp"

namespace vorocrust::features {
namespace {

constexpr double kDefaultSharpAngle = 30 * std::numbers::pi / 180;

SharpBends bends_of(const std::string& model) { return sharp_bends(read_mesh(test::model(model)), kDefaultSharpAngle); }

class Scans : public ::testing::TestWithParam<const char*> {};
class CadParts : public ::testing::TestWithParam<const char*> {};

// Scans and tessellations of curved shapes. ajc_rocker-arm is among them: a part, but as a
// tessellation 80 % of its 1 105 sharp edges bend by less than 45 degrees, in 346 chains of one
// edge at the median, which would each be protected as a crease; the hint names a larger sharp
// angle for such a part.
TEST_P(Scans, LookLikeScans) {
  const SharpBends b = bends_of(GetParam());
  EXPECT_TRUE(b.looks_like_scan()) << b.sharp_edges << " sharp, " << b.near_sharp_angle << " near, " << b.chains
                                   << " chains of median " << b.median_chain;
}
INSTANTIATE_TEST_SUITE_P(SharedModels, Scans,
                         ::testing::Values("igl_bunny.off", "directional_bimba.off", "cgal_elephant.off",
                                           "igl_fertility.off", "igl_camelhead.off", "sandia_bird.obj",
                                           "heptoroid_welded.off", "openmeeg_mne_sample_bem.obj", "cgal_bones.off",
                                           "ajc_rocker-arm.obj"));

TEST_P(CadParts, DoNot) {
  const SharpBends b = bends_of(GetParam());
  EXPECT_FALSE(b.looks_like_scan()) << b.sharp_edges << " sharp, " << b.near_sharp_angle << " near, " << b.chains
                                    << " chains of median " << b.median_chain;
}
// With the smooth shapes whose few sharp edges need no hint (the torus has none, igl_3holes 79 in
// 14 chains).
INSTANTIATE_TEST_SUITE_P(SharedModels, CadParts,
                         ::testing::Values("cgal_fandisk.off", "cgal_joint.off", "netgen_hinge.stl", "sandia_bracket.obj",
                                           "sandia_OneBox.obj", "sandia_non_manifold_box.obj",
                                           "sandia_cube_test_01.obj", "sandia_cube_test_03.obj",
                                           "cgal_polyhedral_complex_patches.obj", "cgal_cubes_edge_contact.off",
                                           "cgal_knot2.off", "sandia_torus.obj", "igl_3holes.off",
                                           "openmeeg_HeadNNc3.obj"));

TEST(SharpBends, CountsTheEdgesNearTheSharpAngleAndTheirChains) {
  // A bunny at 30 degrees: most of its sharp edges bend within 15 degrees more.
  const SharpBends b = bends_of("igl_bunny.off");
  EXPECT_GT(b.sharp_edges, 700u);
  EXPECT_GT(b.near_sharp_angle * 2, b.sharp_edges);
  EXPECT_LE(b.median_chain, 2u);
  // The fandisk's 722 sharp edges are one network of creases, bent far past 30 degrees.
  const SharpBends f = bends_of("cgal_fandisk.off");
  EXPECT_EQ(f.chains, 1u);
  EXPECT_LT(f.near_sharp_angle * 10, f.sharp_edges);
}

}  // namespace
}  // namespace vorocrust::features
