#include <cmath>
#include <cstring>
#include <string>

#include "io/byte_source.hpp"
#include "io/readers.hpp"
#include "io/vertex_welder.hpp"

namespace vorocrust::io {

namespace {

constexpr std::size_t kHeaderBytes = 84;  // 80-byte comment and a little-endian triangle count
constexpr std::size_t kRecordBytes = 50;  // normal, three corners (12 floats), attribute word

std::uint32_t triangle_count(std::string_view bytes) {
  std::uint32_t n = 0;
  std::memcpy(&n, bytes.data() + 80, sizeof n);
  return n;  // little-endian on every machine this library targets
}

bool looks_ascii(std::string_view bytes) {
  // Binary files may also begin with "solid"; one whose size matches its count is binary.
  if (bytes.size() >= kHeaderBytes && kHeaderBytes + kRecordBytes * std::uint64_t(triangle_count(bytes)) == bytes.size()) {
    return false;
  }
  std::size_t i = 0;
  while (i < bytes.size() && (bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\r' || bytes[i] == '\n')) ++i;
  return bytes.substr(i, 5) == "solid";
}

void add_welded_triangle(SurfaceMesh& mesh, VertexWelder& welder, const Point (&corners)[3], Index group,
                         std::uint32_t line, const std::string& file, std::size_t record) {
  const Triangle t{welder.weld(corners[0]), welder.weld(corners[1]), welder.weld(corners[2])};
  if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
    fail(Error::Kind::InvalidGeometry, file, line,
         "facet " + std::to_string(record) + " has two equal corners: a triangle needs three distinct corners");
  }
  mesh.add_triangle(t, group, line);
}

void check_finite(const Point& p, const std::string& file, std::size_t line, std::size_t record) {
  if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) {
    fail(Error::Kind::InvalidGeometry, file, line,
         "facet " + std::to_string(record) + " has a corner that is not a finite number (NaN or infinity)");
  }
}

SurfaceMesh parse_binary(std::string_view bytes, const std::string& file) {
  if (bytes.size() < kHeaderBytes) {
    fail(Error::Kind::UnreadableInput, file, 0,
         "truncated binary STL: the file has " + std::to_string(bytes.size()) +
             " bytes, fewer than the 84-byte header");
  }
  const std::uint64_t n = triangle_count(bytes);
  const std::uint64_t needed = kHeaderBytes + kRecordBytes * n;
  if (bytes.size() < needed) {
    fail(Error::Kind::UnreadableInput, file, 0,
         "truncated binary STL: the header promises " + std::to_string(n) + " triangles (" +
             std::to_string(needed) + " bytes) but the file has " + std::to_string(bytes.size()) +
             " bytes, " + std::to_string((bytes.size() - kHeaderBytes) / kRecordBytes) + " complete triangles");
  }
  SurfaceMesh mesh;
  mesh.groups.push_back({std::filesystem::path(file).stem().string(), file});
  VertexWelder welder(mesh.vertices);
  for (std::uint64_t i = 0; i < n; ++i) {
    const char* record = bytes.data() + kHeaderBytes + kRecordBytes * i;
    Point corners[3];
    for (int c = 0; c < 3; ++c) {
      float xyz[3];
      std::memcpy(xyz, record + 12 + 12 * c, sizeof xyz);
      corners[c] = Point(xyz[0], xyz[1], xyz[2]);
      check_finite(corners[c], file, 0, i);
    }
    add_welded_triangle(mesh, welder, corners, 0, 0, file, i);
  }
  if (mesh.triangles.empty()) fail(Error::Kind::InvalidGeometry, file, 0, "empty mesh: the file has no faces");
  return mesh;
}

SurfaceMesh parse_ascii(std::string_view bytes, const std::string& file) {
  LineCursor in(bytes, file, /*hash_comments=*/false);
  SurfaceMesh mesh;
  VertexWelder welder(mesh.vertices);
  const std::string stem = std::filesystem::path(file).stem().string();
  Index group = 0;
  bool in_solid = false, in_facet = false;
  int corner = 0;
  std::size_t record = 0;
  std::uint32_t facet_line = 0;
  Point corners[3];
  while (in.next_nonempty()) {
    const std::string_view keyword = in.token();
    if (keyword == "solid") {
      if (in_solid) in.fail(Error::Kind::UnreadableInput, "'solid' inside another solid (missing 'endsolid')");
      const std::string_view name = in.rest_of_line();
      group = static_cast<Index>(mesh.groups.size());
      mesh.groups.push_back({name.empty() ? stem : std::string(name), file});
      in_solid = true;
    } else if (keyword == "facet") {
      if (!in_solid) in.fail(Error::Kind::UnreadableInput, "'facet' outside a solid");
      if (in_facet) in.fail(Error::Kind::UnreadableInput, "'facet' inside another facet (missing 'endfacet')");
      in_facet = true;
      corner = 0;
      facet_line = static_cast<std::uint32_t>(in.line_number());
    } else if (keyword == "vertex") {
      if (!in_facet) in.fail(Error::Kind::UnreadableInput, "'vertex' outside a facet");
      if (corner == 3) in.fail(Error::Kind::UnreadableInput, "a facet with more than 3 vertices");
      const double x = in.require_double("an x coordinate");
      const double y = in.require_double("a y coordinate");
      const double z = in.require_double("a z coordinate");
      corners[corner] = Point(x, y, z);
      check_finite(corners[corner], file, in.line_number(), record);
      ++corner;
    } else if (keyword == "endfacet") {
      if (!in_facet) in.fail(Error::Kind::UnreadableInput, "'endfacet' without 'facet'");
      if (corner != 3) in.fail(Error::Kind::UnreadableInput, "a facet needs 3 vertices, this one has " + std::to_string(corner));
      add_welded_triangle(mesh, welder, corners, group, facet_line, file, record);
      ++record;
      in_facet = false;
    } else if (keyword == "endsolid") {
      if (in_facet) in.fail(Error::Kind::UnreadableInput, "'endsolid' inside a facet");
      in_solid = false;
    } else if (keyword != "outer" && keyword != "endloop") {
      in.fail(Error::Kind::UnreadableInput, "unexpected " + quote(keyword) + " in an ASCII STL file");
    }
  }
  if (in_facet) in.fail(Error::Kind::UnreadableInput, "truncated: the file ends inside a facet");
  if (mesh.triangles.empty()) fail(Error::Kind::InvalidGeometry, file, 0, "empty mesh: the file has no faces");
  return mesh;
}

}  // namespace

SurfaceMesh parse_stl(std::string_view bytes, const std::string& file) {
  return looks_ascii(bytes) ? parse_ascii(bytes, file) : parse_binary(bytes, file);
}

}  // namespace vorocrust::io
