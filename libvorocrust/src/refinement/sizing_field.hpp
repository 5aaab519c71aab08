// Internal: the sizing field sz of paper 2.1, the largest radius a ball may have at a point.
//
// sz(p) = min(max_size, interpolated size) where the interpolation, when a sizing file is given,
// is inverse-distance weighting over the 8 nearest given points. The file format (documented in
// the README) is text: one point per line, `x y z size`, `#` starting a comment.
#pragma once

#include <filesystem>
#include <limits>
#include <memory>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

class SizingField {
 public:
  explicit SizingField(double max_size = std::numeric_limits<double>::infinity());
  // Throws Error(UnreadableInput) naming the line of a malformed entry or a size that is not positive.
  // `planar`: lines may also be "x y size" (2D domains, z = 0).
  SizingField(double max_size, const std::filesystem::path& sizing_file, bool planar = false);
  ~SizingField();
  SizingField(SizingField&&) noexcept;

  double operator()(const Point& p) const;
  // Whether the field is max_size everywhere (no sizing file).
  bool uniform() const { return !samples_; }

 private:
  struct Samples;
  double max_size_;
  std::unique_ptr<Samples> samples_;
};

}  // namespace vorocrust
