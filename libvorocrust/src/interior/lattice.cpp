// The lattice of InteriorMode::Lattice (paper Figure 5f).
#include "interior/interior_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "refinement/sizing_field.hpp"

namespace vorocrust::interior {

// A cubic lattice over the regions deep enough for its cells; the rest is left to random seeds.
void InteriorSampler::place_lattice() {
  std::vector<double> radii;
  for (const Seed& s : surface_) radii.push_back(s.radius);
  std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
  const Point centre = 0.5 * (domain_.lo + domain_.hi);
  const double spacing = std::min(radii[radii.size() / 2], sizing_(centre));
  // A ball of this radius about each lattice point covers its lattice cube, so no random seed
  // lands between lattice points.
  const double radius = 0.87 * spacing;
  Eigen::Vector3i lo, hi;
  for (int k = 0; k < 3; ++k) {
    lo[k] = static_cast<int>(std::floor((domain_.lo[k] - centre[k]) / spacing));
    hi[k] = static_cast<int>(std::ceil((domain_.hi[k] - centre[k]) / spacing));
  }
  for (int i = lo[0]; i <= hi[0]; ++i) {
    for (int j = lo[1]; j <= hi[1]; ++j) {
      for (int k = lo[2]; k <= hi[2]; ++k) {
        const Point z = centre + spacing * Point(i, j, k);
        const std::optional<Seed> seed = admit(z);
        if (seed && seed->region != kOutsideRegion && seed->radius >= radius) {
          add({z, seed->region, radius, SeedKind::Interior});
          ++stats_.lattice_seeds;
        }
      }
    }
    check_cancel();
  }
}

}  // namespace vorocrust::interior
