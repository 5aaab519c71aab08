// `vorocrust check-balls`: the arguments of the independent ball checker (tools/check_balls) and
// its entry point, which returns an exit code (exit_codes.hpp): 0 when every ball condition holds,
// 8 when some does not.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "domain_args.hpp"
#include "vorocrust/mesher.hpp"

namespace vorocrust::cli {

// The input meshes, then the balls CSV, as the last of `files`.
struct CheckBallsArgs {
  std::vector<std::string> files;
  bool smooth = false;
  std::optional<double> sharp_angle_degrees;  // unset: the mesher's default for the mode
  double lipschitz = MeshOptions{}.lipschitz;
  std::size_t face_samples = 200000;
  std::size_t crease_samples = 50000;
  std::uint64_t seed = 1;
  bool json = false;
  DomainArgs domain;  // as the run that made the balls: its box and self-intersections
};

int run_check_balls(const CheckBallsArgs& args);

}  // namespace vorocrust::cli
