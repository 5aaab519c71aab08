#include <cmath>

#include "vorocrust/error.hpp"
#include "vorocrust/mesher.hpp"

namespace vorocrust {

void MeshOptions::check() const {
  if (!(lipschitz > 0 && lipschitz < 1)) {
    throw Error(Error::Kind::Usage, "--lipschitz must lie strictly between 0 and 1, got " + std::to_string(lipschitz));
  }
  if (!(sharp_angle_degrees > 0 && sharp_angle_degrees < 90)) {
    throw Error(Error::Kind::Usage,
                "--sharp-angle must lie strictly between 0 and 90 degrees, got " + std::to_string(sharp_angle_degrees));
  }
  if (!(max_size > 0)) throw Error(Error::Kind::Usage, "--max-size must be positive, got " + std::to_string(max_size));
  if (threads < 0) throw Error(Error::Kind::Usage, "--threads must be 0 (all) or positive");
}

MeshResult generate_mesh(const SurfaceMesh& input, const MeshOptions& options, const ProgressCallback& progress) {
  options.check();
  if (progress && !progress({"refinement", 0.0})) throw Error(Error::Kind::Cancelled, "cancelled");
  (void)input;
  throw Error(Error::Kind::NotImplemented,
              "not yet: the refinement stage (protecting balls, paper section 2.3) is not implemented in this "
              "version; `vorocrust info` reads and validates the input");
}

}  // namespace vorocrust
