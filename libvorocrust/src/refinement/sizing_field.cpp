#include "refinement/sizing_field.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "io/byte_source.hpp"
#include "geometry/point_cloud.hpp"

namespace vorocrust {

namespace {
using Adaptor = PointCloudAdaptor<Point, IdentityPosition>;
using Tree = StaticKdTree<Adaptor>;
constexpr std::size_t kNeighbours = 8;
}  // namespace

struct SizingField::Samples {
  std::vector<Point> points;
  std::vector<double> sizes;
  Adaptor adaptor;
  std::unique_ptr<Tree> tree;
};

SizingField::SizingField(double max_size) : max_size_(max_size) {}

SizingField::SizingField(double max_size, const std::filesystem::path& sizing_file, bool planar)
    : max_size_(max_size), samples_(std::make_unique<Samples>()) {
  const std::string bytes = io::read_file_bytes(sizing_file);
  io::LineCursor in(bytes, sizing_file.string());
  while (in.next_nonempty()) {
    const double x = in.require_double("an x coordinate");
    const double y = in.require_double("a y coordinate");
    double z = in.require_double(planar ? "a size" : "a z coordinate");
    double size = 0;
    if (const std::string_view last = in.token(); planar && last.empty()) {
      size = std::exchange(z, 0.0);
    } else if (last.empty() || !io::parse_double(last, size)) {
      in.fail(Error::Kind::UnreadableInput, "expected a size, found " + (last.empty() ? std::string("nothing") : io::quote(last)));
    }
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) {
      in.fail(Error::Kind::UnreadableInput, "sizing point is not finite");
    }
    if (!(size > 0) || !std::isfinite(size)) in.fail(Error::Kind::UnreadableInput, "sizes must be positive and finite");
    samples_->points.emplace_back(x, y, z);
    samples_->sizes.push_back(size);
  }
  if (samples_->points.empty()) io::fail(Error::Kind::UnreadableInput, sizing_file.string(), 0, "the sizing file has no points");
  samples_->adaptor.items = &samples_->points;
  samples_->tree = std::make_unique<Tree>(3, samples_->adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16));
}

SizingField::~SizingField() = default;
SizingField::SizingField(SizingField&&) noexcept = default;

double SizingField::operator()(const Point& p) const {
  if (!samples_) return max_size_;
  const std::size_t k = std::min(kNeighbours, samples_->points.size());
  std::uint32_t index[kNeighbours];
  double squared[kNeighbours];
  const double query[3] = {p.x(), p.y(), p.z()};
  nanoflann::KNNResultSet<double, std::uint32_t> result(k);
  result.init(index, squared);
  samples_->tree->findNeighbors(result, query, nanoflann::SearchParams());
  // Samples so far away that their squared distance overflows are never found; with none left,
  // the field is unknown here and the largest size holds.
  const std::size_t found = result.size();
  if (found == 0) return max_size_;
  double weight_sum = 0, value = 0, lo = std::numeric_limits<double>::infinity(), hi = 0;
  for (std::size_t i = 0; i < found; ++i) {
    const double size = samples_->sizes[index[i]];
    if (squared[i] == 0) return std::min(max_size_, size);
    const double w = 1.0 / squared[i];
    weight_sum += w;
    value += w * size;
    lo = std::min(lo, size);
    hi = std::max(hi, size);
  }
  // Weights that underflow to zero leave the nearest sizes' range to choose from.
  if (!(weight_sum > 0)) return std::min(max_size_, lo);
  // A weighted mean lies between its values; rounding must not push it past them.
  return std::min(max_size_, std::clamp(value / weight_sum, lo, hi));
}

}  // namespace vorocrust
