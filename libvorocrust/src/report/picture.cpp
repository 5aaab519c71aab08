// Pictures of meshes for report.html: a small z-buffer rasteriser and a PNG encoder.
#include "report/picture.hpp"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "vorocrust/error.hpp"

namespace vorocrust::report {

Rgb scaled(Rgb colour, double factor) {
  const auto channel = [&](std::uint8_t c) {
    return static_cast<std::uint8_t>(std::clamp(std::lround(c * factor), 0L, 255L));
  };
  return {channel(colour.r), channel(colour.g), channel(colour.b)};
}

Rgb region_colour(std::int32_t label) {
  // Colours told apart by most readers, colour-blind ones included (Paul Tol's "bright" and
  // "vibrant" sets), repeating past twelve regions.
  static constexpr std::array<Rgb, 12> kColours = {{{68, 119, 170},
                                                   {238, 102, 119},
                                                   {34, 136, 51},
                                                   {204, 187, 68},
                                                   {102, 204, 238},
                                                   {170, 51, 119},
                                                   {238, 119, 51},
                                                   {0, 153, 136},
                                                   {51, 34, 136},
                                                   {136, 204, 238},
                                                   {204, 102, 119},
                                                   {153, 153, 51}}};
  if (label <= 0) return {170, 170, 170};
  return kColours[static_cast<std::size_t>(label - 1) % kColours.size()];
}

Picture::Picture(int width, int height, Rgb background)
    : width_(width),
      height_(height),
      rgb_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3),
      depth_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), std::numeric_limits<double>::infinity()) {
  for (std::size_t i = 0; i < depth_.size(); ++i) {
    rgb_[3 * i] = background.r;
    rgb_[3 * i + 1] = background.g;
    rgb_[3 * i + 2] = background.b;
  }
}

Rgb Picture::pixel(int x, int y) const {
  const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x));
  return {rgb_[i], rgb_[i + 1], rgb_[i + 2]};
}

void Picture::plot(int x, int y, double depth, Rgb colour) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
  const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
  if (!(depth < depth_[i])) return;
  depth_[i] = depth;
  rgb_[3 * i] = colour.r;
  rgb_[3 * i + 1] = colour.g;
  rgb_[3 * i + 2] = colour.b;
}

void Picture::draw_triangle(const std::array<Point, 3>& c, Rgb colour) {
  const auto edge = [](const Point& a, const Point& b, double x, double y) {
    return (b.x() - a.x()) * (y - a.y()) - (b.y() - a.y()) * (x - a.x());
  };
  const double area = edge(c[0], c[1], c[2].x(), c[2].y());
  if (!(std::abs(area) > 1e-12) || !std::isfinite(area)) return;  // edge-on, or not finite
  const double low_x = std::min({c[0].x(), c[1].x(), c[2].x()}), high_x = std::max({c[0].x(), c[1].x(), c[2].x()});
  const double low_y = std::min({c[0].y(), c[1].y(), c[2].y()}), high_y = std::max({c[0].y(), c[1].y(), c[2].y()});
  if (high_x < 0 || high_y < 0 || low_x >= width_ || low_y >= height_) return;
  // Clamped as doubles: a corner far outside the picture must not overflow an int.
  const auto pixel_range = [](double low, double high, int size) {
    return std::pair{static_cast<int>(std::clamp(std::floor(low), 0.0, size - 1.0)),
                     static_cast<int>(std::clamp(std::ceil(high), 0.0, size - 1.0))};
  };
  const auto [x0, x1] = pixel_range(low_x, high_x, width_);
  const auto [y0, y1] = pixel_range(low_y, high_y, height_);
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const double px = x + 0.5, py = y + 0.5;
      // Barycentric weights, each of the sign of `area` inside.
      const double w0 = edge(c[1], c[2], px, py) / area, w1 = edge(c[2], c[0], px, py) / area;
      const double w2 = 1 - w0 - w1;
      if (w0 < 0 || w1 < 0 || w2 < 0) continue;
      plot(x, y, w0 * c[0].z() + w1 * c[1].z() + w2 * c[2].z(), colour);
    }
  }
}

void Picture::draw_line(const Point& a, const Point& b, Rgb colour) {
  // Ahead of the faces the line bounds, in depth units (pixels): an edge shows over its faces.
  constexpr double kAhead = 0.75;
  // The part inside the picture (Liang and Barsky's clipping), so a line's cost is bounded by
  // the picture's size whatever its length.
  double t0 = 0, t1 = 1;
  const Point d = b - a;
  const auto clip = [&](double p, double q) {
    if (p == 0) return q >= 0;
    const double t = q / p;
    if (p < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
    return t0 <= t1;
  };
  if (!(clip(-d.x(), a.x()) && clip(d.x(), width_ - a.x()) && clip(-d.y(), a.y()) && clip(d.y(), height_ - a.y()))) return;
  const Point from = a + t0 * d, to = a + t1 * d;
  const double steps = std::ceil(std::max(std::abs(to.x() - from.x()), std::abs(to.y() - from.y())));
  if (!std::isfinite(steps)) return;
  const int n = std::max(1, static_cast<int>(steps));
  for (int k = 0; k <= n; ++k) {
    const Point p = from + (to - from) * (static_cast<double>(k) / n);
    plot(static_cast<int>(std::floor(p.x())), static_cast<int>(std::floor(p.y())), p.z() - kAhead, colour);
  }
}

void Picture::clear_depth() { std::fill(depth_.begin(), depth_.end(), std::numeric_limits<double>::infinity()); }

namespace {

void put_u32(std::string& out, std::uint32_t v) {
  for (int shift : {24, 16, 8, 0}) out += static_cast<char>((v >> shift) & 0xff);
}

void put_chunk(std::string& png, const char* type, const std::string& data) {
  put_u32(png, static_cast<std::uint32_t>(data.size()));
  const std::string typed = std::string(type, 4) + data;
  png += typed;
  put_u32(png, static_cast<std::uint32_t>(
                   crc32(0L, reinterpret_cast<const Bytef*>(typed.data()), static_cast<uInt>(typed.size()))));
}

}  // namespace

std::string encode_png(const Picture& picture) {
  const auto width = static_cast<std::size_t>(picture.width()), height = static_cast<std::size_t>(picture.height());
  // Each row starts with its filter type, 0 (none).
  std::string raw;
  raw.reserve(height * (1 + 3 * width));
  for (std::size_t y = 0; y < height; ++y) {
    raw += '\0';
    raw.append(reinterpret_cast<const char*>(picture.rgb().data() + 3 * width * y), 3 * width);
  }
  uLongf packed_size = compressBound(static_cast<uLong>(raw.size()));
  std::string packed(packed_size, '\0');
  if (compress2(reinterpret_cast<Bytef*>(packed.data()), &packed_size, reinterpret_cast<const Bytef*>(raw.data()),
                static_cast<uLong>(raw.size()), 6) != Z_OK) {
    throw Error(Error::Kind::Output, "cannot compress a picture (zlib)");
  }
  packed.resize(packed_size);

  std::string header;
  put_u32(header, static_cast<std::uint32_t>(width));
  put_u32(header, static_cast<std::uint32_t>(height));
  header += std::string("\x08\x02\x00\x00\x00", 5);  // 8 bits, RGB, deflate, adaptive filters, no interlace
  std::string png = "\x89PNG\r\n\x1a\n";
  put_chunk(png, "IHDR", header);
  put_chunk(png, "IDAT", packed);
  put_chunk(png, "IEND", "");
  return png;
}

View::View(const Point& low, const Point& high, const Point& forward, const Point& up, int width, int height,
           double margin)
    : centre_((low + high) / 2), forward_(forward.normalized()) {
  right_ = forward_.cross(up).normalized();
  up_ = right_.cross(forward_);
  // From behind the viewer's right shoulder, so faces at different slopes read apart.
  light_ = (-forward_ + 0.45 * up_ + 0.3 * right_).normalized();
  double extent_x = 0, extent_y = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Point p((corner & 1) ? high.x() : low.x(), (corner & 2) ? high.y() : low.y(), (corner & 4) ? high.z() : low.z());
    extent_x = std::max(extent_x, std::abs((p - centre_).dot(right_)));
    extent_y = std::max(extent_y, std::abs((p - centre_).dot(up_)));
  }
  half_width_ = width / 2.0;
  half_height_ = height / 2.0;
  const double room_x = std::max(1.0, half_width_ - margin), room_y = std::max(1.0, half_height_ - margin);
  scale_ = std::min(extent_x > 0 ? room_x / extent_x : 1.0, extent_y > 0 ? room_y / extent_y : 1.0);
  if (!std::isfinite(scale_) || scale_ <= 0) scale_ = 1;
}

Point View::to_screen(const Point& p) const {
  const Point d = p - centre_;
  return {half_width_ + scale_ * d.dot(right_), half_height_ - scale_ * d.dot(up_), scale_ * d.dot(forward_)};
}

double View::shade(const Point& normal) const { return 0.35 + 0.65 * std::abs(normal.dot(light_)); }

}  // namespace vorocrust::report
