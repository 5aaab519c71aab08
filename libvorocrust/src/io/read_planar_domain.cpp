// Reading 2D domains: Triangle's .poly and OBJ polylines (paper 2.6).
#include <algorithm>
#include <cmath>
#include <string>

#include "io/byte_source.hpp"
#include "vorocrust/plane.hpp"

namespace vorocrust {

namespace {

using io::LineCursor;

std::int64_t require_count(LineCursor& in, const char* what) {
  const std::int64_t n = in.require_int(what);
  if (n < 0) in.fail(Error::Kind::UnreadableInput, std::string(what) + " is negative");
  // No line is shorter than two bytes, so a count beyond the file's size cannot be honest.
  if (static_cast<std::size_t>(n) > in.remaining_text().size()) {
    in.fail(Error::Kind::UnreadableInput, std::string(what) + " " + std::to_string(n) + " exceeds what the file holds");
  }
  return n;
}

bool require_next(LineCursor& in, const char* what) {
  if (!in.next_nonempty()) io::fail(Error::Kind::UnreadableInput, in.file(), in.line_number(), "the file ends before " + std::string(what));
  return true;
}

double finite(LineCursor& in, const char* what) {
  const double x = in.require_double(what);
  if (!std::isfinite(x)) in.fail(Error::Kind::UnreadableInput, std::string(what) + " is not finite");
  return x;
}

// Triangle's .poly: a vertex block (or 0 vertices, meaning a separate .node file), segments,
// holes and the optional regional attributes. Vertex numbers start at the first one's.
PlanarDomain parse_poly(std::string_view bytes, const std::string& file) {
  LineCursor in(bytes, file);
  PlanarDomain d;
  d.file = file;
  require_next(in, "the vertex count");
  const std::int64_t vertices = require_count(in, "the vertex count");
  if (vertices == 0) {
    in.fail(Error::Kind::UnreadableInput, "the vertices are in a separate .node file; put them in the .poly file");
  }
  const std::int64_t dimension = in.require_int("the dimension");
  if (dimension != 2) in.fail(Error::Kind::UnreadableInput, "the dimension is " + std::to_string(dimension) + ", not 2");
  const std::int64_t attributes = in.require_int("the attribute count");
  const std::int64_t vertex_markers = in.require_int("the boundary marker count");
  if (attributes < 0 || vertex_markers < 0 || vertex_markers > 1) {
    in.fail(Error::Kind::UnreadableInput, "the attribute count must be 0 or more and the marker count 0 or 1");
  }
  std::int64_t first = 0;
  for (std::int64_t v = 0; v < vertices; ++v) {
    require_next(in, "every vertex is read");
    const std::int64_t number = in.require_int("a vertex number");
    if (v == 0) {
      if (number != 0 && number != 1) in.fail(Error::Kind::UnreadableInput, "vertices must be numbered from 0 or 1");
      first = number;
    } else if (number != first + v) {
      in.fail(Error::Kind::UnreadableInput,
              "vertex number " + std::to_string(number) + " where " + std::to_string(first + v) + " was expected");
    }
    const double x = finite(in, "an x coordinate");
    const double y = finite(in, "a y coordinate");
    d.points.emplace_back(x, y);
  }
  require_next(in, "the segment count");
  const std::int64_t segments = require_count(in, "the segment count");
  for (std::int64_t s = 0; s < segments; ++s) {
    require_next(in, "every segment is read");
    in.require_int("a segment number");
    std::array<Index, 2> ends{};
    for (Index& e : ends) {
      const std::int64_t v = in.require_int("a segment's end point") - first;
      if (v < 0 || v >= vertices) {
        in.fail(Error::Kind::UnreadableInput, "segment end " + std::to_string(v + first) + " names no vertex (they are " +
                                                  std::to_string(first) + " to " + std::to_string(first + vertices - 1) + ")");
      }
      e = static_cast<Index>(v);
    }
    d.segments.push_back(ends);
    d.segment_lines.push_back(in.line_number());
  }
  if (!in.next_nonempty()) return d;  // Triangle allows the hole count to be left out
  const std::int64_t holes = require_count(in, "the hole count");
  for (std::int64_t h = 0; h < holes; ++h) {
    require_next(in, "every hole is read");
    in.require_int("a hole number");
    const double x = finite(in, "a hole's x");
    const double y = finite(in, "a hole's y");
    d.holes.emplace_back(x, y);
  }
  if (!in.next_nonempty()) return d;
  const std::int64_t regions = require_count(in, "the region count");
  for (std::int64_t r = 0; r < regions; ++r) {
    require_next(in, "every region is read");
    in.require_int("a region number");
    RegionPoint p;
    p.at.x() = finite(in, "a region's x");
    p.at.y() = finite(in, "a region's y");
    const double attribute = finite(in, "a region's attribute");
    if (attribute != std::floor(attribute) || attribute < 1 || attribute > 1e9) {
      in.fail(Error::Kind::UnreadableInput, "a region's attribute is its material label: a whole number from 1, not " +
                                                std::to_string(attribute));
    }
    p.label = static_cast<std::int32_t>(attribute);
    p.line = in.line_number();
    d.regions.push_back(p);
  }
  return d;
}

// OBJ polylines: `v x y z` (one z for all) and `l a b c ...`, indices from 1 or negative.
PlanarDomain parse_obj_lines(std::string_view bytes, const std::string& file) {
  LineCursor in(bytes, file);
  PlanarDomain d;
  d.file = file;
  std::optional<double> plane_z;
  while (in.next_nonempty()) {
    const std::string_view keyword = in.token();
    if (keyword == "v") {
      const double x = finite(in, "an x coordinate");
      const double y = finite(in, "a y coordinate");
      const std::string_view zt = in.token();
      double z = 0;
      if (!zt.empty() && (!io::parse_double(zt, z) || !std::isfinite(z))) {
        in.fail(Error::Kind::UnreadableInput, "expected a z coordinate, found " + io::quote(zt));
      }
      if (!plane_z) plane_z = z;
      if (z != *plane_z) {
        in.fail(Error::Kind::InvalidGeometry, "a 2D domain lies in one plane z = const; this vertex has z = " +
                                                  std::to_string(z) + ", the first had " + std::to_string(*plane_z));
      }
      d.points.emplace_back(x, y);
    } else if (keyword == "l") {
      std::int64_t previous = -1;
      for (std::string_view t = in.token(); !t.empty(); t = in.token()) {
        std::int64_t index = 0;
        const std::string_view v = t.substr(0, t.find('/'));
        if (!io::parse_int(v, index) || index == 0) in.fail(Error::Kind::UnreadableInput, "expected a vertex index from 1, found " + io::quote(t));
        if (index < 0) index += static_cast<std::int64_t>(d.points.size()) + 1;
        if (index < 1 || index > static_cast<std::int64_t>(d.points.size())) {
          in.fail(Error::Kind::UnreadableInput, "vertex index " + std::string(v) + " names no vertex read so far");
        }
        if (previous >= 0) {
          d.segments.push_back({static_cast<Index>(previous), static_cast<Index>(index - 1)});
          d.segment_lines.push_back(in.line_number());
        }
        previous = index - 1;
      }
      if (previous < 0) in.fail(Error::Kind::UnreadableInput, "a line element needs at least two vertices");
    } else if (keyword == "f") {
      in.fail(Error::Kind::UnreadableInput, "a 2D domain is given by line elements (l), not faces");
    }
    // Other keywords (vt, vn, g, o, s, usemtl, mtllib) do not shape a 2D domain.
  }
  return d;
}

}  // namespace

PlanarDomain read_planar_domain(const std::filesystem::path& path) {
  const std::string bytes = io::read_file_bytes(path);
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  if (extension == ".poly") return parse_poly(bytes, path.string());
  if (extension == ".obj") return parse_obj_lines(bytes, path.string());
  throw Error(Error::Kind::UnreadableInput, "a 2D domain is read from .poly (Triangle) or .obj (polylines), not '" + extension + "'",
              {.file = path.string()});
}

}  // namespace vorocrust
