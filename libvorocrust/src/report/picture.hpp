// Pictures of meshes for report.html: flat-shaded triangles and lines rasterised into an RGB
// image with a depth buffer, seen along one direction without perspective, encoded as PNG.
//
// Contract:
// - Screen coordinates are pixels, x to the right and y down, pixel (i, j) covering
//   [i, i + 1) x [j, j + 1); a primitive colours the pixels whose centres it covers (a line the
//   pixels it passes). Depth is a distance along the view: smaller is nearer. A primitive
//   colours a pixel only where it is nearer than what the pixel holds (lines by a small margin,
//   so the edges of a face show over it); clear_depth() puts what follows in front of everything
//   drawn before. Parts outside the picture are clipped.
// - encode_png gives a PNG file (8-bit RGB, no interlace) of the picture; Error(Output) when
//   zlib fails.
// - View projects a box's contents to fill a picture, keeping proportions, with a margin.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::report {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

// `colour` darkened or lightened by `factor` (0: black, 1: itself, up to 255 per channel).
Rgb scaled(Rgb colour, double factor);

// A distinct colour for each region label, grey for 0 (outside).
Rgb region_colour(std::int32_t label);

class Picture {
 public:
  Picture(int width, int height, Rgb background);

  int width() const { return width_; }
  int height() const { return height_; }
  Rgb pixel(int x, int y) const;
  const std::vector<std::uint8_t>& rgb() const { return rgb_; }  // row by row, top first

  // Screen points: x, y in pixels, z the depth.
  void draw_triangle(const std::array<Point, 3>& corners, Rgb colour);
  void draw_line(const Point& a, const Point& b, Rgb colour);
  void clear_depth();

 private:
  void plot(int x, int y, double depth, Rgb colour);

  int width_, height_;
  std::vector<std::uint8_t> rgb_;
  std::vector<double> depth_;
};

std::string encode_png(const Picture& picture);

class View {
 public:
  // Looking along `forward` with `up` (not parallel to it) pointing up the picture, at the box
  // [low, high] scaled to fill a width x height picture less `margin` pixels on each side.
  View(const Point& low, const Point& high, const Point& forward, const Point& up, int width, int height,
       double margin = 16);

  Point to_screen(const Point& p) const;
  // How bright a face of unit normal `normal` looks, lit from behind the viewer: 0.35 edge-on
  // to 1 facing the light, whichever side faces it.
  double shade(const Point& normal) const;
  const Point& forward() const { return forward_; }

 private:
  Point centre_, forward_, right_, up_, light_;
  double scale_ = 1, half_width_ = 0, half_height_ = 0;
};

}  // namespace vorocrust::report
