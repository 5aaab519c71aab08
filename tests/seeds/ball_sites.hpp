// Test helper: the site of a hand-made ball, on a patch unless told otherwise.
#pragma once

#include "refinement/surface_site.hpp"

namespace vorocrust::test {

inline SurfaceSite site_at(const Point& p, StratumType type = StratumType::Patch) {
  SurfaceSite s;
  s.position = p;
  s.type = type;
  return s;
}

}  // namespace vorocrust::test
