#include <string>

#include "io/byte_source.hpp"
#include "io/readers.hpp"
#include "io/polygon.hpp"

namespace vorocrust::io {

SurfaceMesh parse_off(std::string_view bytes, const std::string& file) {
  LineCursor in(bytes, file);
  if (!in.next_nonempty()) fail(Error::Kind::UnreadableInput, file, 0, "empty file: no OFF header");
  std::string_view header = in.token();
  // OFF variants carry extra per-vertex values (colours, normals, texture) that are ignored.
  static constexpr std::string_view kVariants[] = {"OFF", "COFF", "NOFF", "CNOFF", "STOFF", "STCOFF", "STNOFF", "STCNOFF"};
  bool known = false;
  for (std::string_view v : kVariants) known = known || header == v;
  if (!known) in.fail(Error::Kind::UnreadableInput, "not an OFF file: expected the header 'OFF', found " + quote(header));
  std::string_view tok = in.token();
  if (tok == "BINARY") in.fail(Error::Kind::UnreadableInput, "binary OFF is not supported; write it as text");
  if (tok.empty()) {
    if (!in.next_nonempty()) in.fail(Error::Kind::UnreadableInput, "truncated: the counts line is missing");
    tok = in.token();
  }
  std::int64_t nv = 0, nf = 0;
  if (!parse_int(tok, nv)) in.fail(Error::Kind::UnreadableInput, "expected the vertex count, found " + quote(tok));
  nf = in.require_int("the face count");
  if (nv < 0 || nf < 0) in.fail(Error::Kind::UnreadableInput, "negative vertex or face count");
  const std::size_t plausible = bytes.size() / 2 + 1;  // each entry needs at least two bytes
  if (static_cast<std::size_t>(nv) > plausible || static_cast<std::size_t>(nf) > plausible) {
    in.fail(Error::Kind::UnreadableInput, "the header promises " + std::to_string(nv) + " vertices and " +
                                              std::to_string(nf) + " faces, more than a file of " +
                                              std::to_string(bytes.size()) + " bytes can hold");
  }

  SurfaceMesh mesh;
  mesh.groups.push_back({std::filesystem::path(file).stem().string(), file});
  mesh.vertices.reserve(static_cast<std::size_t>(nv));
  std::vector<std::uint32_t> vertex_lines;
  vertex_lines.reserve(static_cast<std::size_t>(nv));
  for (std::int64_t v = 0; v < nv; ++v) {
    if (!in.next_nonempty()) {
      in.fail(Error::Kind::UnreadableInput, "truncated: the header promises " + std::to_string(nv) +
                                                " vertices, the file ends after " + std::to_string(v));
    }
    const double x = in.require_double("an x coordinate");
    const double y = in.require_double("a y coordinate");
    const double z = in.require_double("a z coordinate");
    mesh.vertices.emplace_back(x, y, z);
    vertex_lines.push_back(static_cast<std::uint32_t>(in.line_number()));
  }
  PolygonBuffer polygon;
  for (std::int64_t f = 0; f < nf; ++f) {
    if (!in.next_nonempty()) {
      in.fail(Error::Kind::UnreadableInput, "truncated: the header promises " + std::to_string(nf) +
                                                " faces, the file ends after " + std::to_string(f));
    }
    const std::int64_t n = in.require_int("the face's corner count");
    if (n < 3) in.fail(Error::Kind::UnreadableInput, "a face needs at least 3 corners, this one has " + std::to_string(n));
    if (n > nv) in.fail(Error::Kind::UnreadableInput, "a face with " + std::to_string(n) + " corners in a mesh of " + std::to_string(nv) + " vertices");
    polygon.clear();
    for (std::int64_t k = 0; k < n; ++k) {
      const std::int64_t index = in.require_int("a vertex index");
      if (index < 0 || index >= nv) {
        in.fail(Error::Kind::UnreadableInput, "vertex index " + std::to_string(index) +
                                                  " is out of range: the file has " + std::to_string(nv) +
                                                  " vertices (0-based)");
      }
      polygon.push_back(static_cast<Index>(index));
    }
    add_polygon(mesh, polygon, 0, static_cast<std::uint32_t>(in.line_number()), file);
  }
  check_parsed_mesh(mesh, file, vertex_lines);
  return mesh;
}

}  // namespace vorocrust::io
