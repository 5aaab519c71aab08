#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "io/byte_source.hpp"
#include "io/polygon.hpp"
#include "io/readers.hpp"
#include "io/region_labels.hpp"
#include "io/text_numbers.hpp"

namespace vorocrust::io {

namespace {

// A vertex index as the file gives it, however large: the cast of 3e124 to an integer, which a
// message once made, is undefined.
std::string index_text(double value) {
  std::string out;
  if (std::abs(value) < 1e15) append_number(out, static_cast<long long>(value));
  else append_number(out, value);
  return out;
}

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

bool parse_type(std::string_view name, PlyType& type) {
  struct Entry { std::string_view name; PlyType type; };
  static constexpr Entry kTypes[] = {
      {"char", PlyType::Int8},     {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
      {"uint8", PlyType::UInt8},   {"short", PlyType::Int16},     {"int16", PlyType::Int16},
      {"ushort", PlyType::UInt16}, {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
      {"int32", PlyType::Int32},   {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
      {"float", PlyType::Float32}, {"float32", PlyType::Float32}, {"double", PlyType::Float64},
      {"float64", PlyType::Float64}};
  for (const Entry& e : kTypes) {
    if (e.name == name) {
      type = e.type;
      return true;
    }
  }
  return false;
}

std::size_t type_size(PlyType t) {
  switch (t) {
    case PlyType::Int8: case PlyType::UInt8: return 1;
    case PlyType::Int16: case PlyType::UInt16: return 2;
    case PlyType::Int32: case PlyType::UInt32: case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
  }
  return 1;
}

struct Property {
  std::string name;
  bool is_list = false;
  PlyType count_type = PlyType::UInt8;
  PlyType type = PlyType::Float32;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

enum class Encoding { Ascii, BinaryLittle, BinaryBig };

// Reads the body's values one at a time, as text tokens or binary words, with bounds checks.
class BodyReader {
 public:
  BodyReader(std::string_view body, Encoding encoding, std::string file, std::size_t header_lines,
             std::size_t header_bytes)
      : encoding_(encoding), text_(body, file, false), body_(body), file_(std::move(file)),
        header_lines_(header_lines), header_bytes_(header_bytes) {}

  double read(PlyType type, const Element& element, std::uint64_t instance) {
    if (encoding_ == Encoding::Ascii) {
      std::string_view tok = text_.token();
      while (tok.empty()) {
        if (!text_.next_nonempty()) truncated(element, instance);
        tok = text_.token();
      }
      double value = 0;
      if (!parse_double(tok, value)) {
        fail(Error::Kind::UnreadableInput, file_, line(), "expected a number in element '" + element.name + "', found " + quote(tok));
      }
      return value;
    }
    const std::size_t size = type_size(type);
    if (pos_ + size > body_.size()) truncated(element, instance);
    unsigned char raw[8];
    std::memcpy(raw, body_.data() + pos_, size);
    pos_ += size;
    const bool swap = (encoding_ == Encoding::BinaryBig) == (std::endian::native == std::endian::little);
    if (swap) std::reverse(raw, raw + size);
    switch (type) {
      case PlyType::Int8: { std::int8_t v; std::memcpy(&v, raw, 1); return v; }
      case PlyType::UInt8: { std::uint8_t v; std::memcpy(&v, raw, 1); return v; }
      case PlyType::Int16: { std::int16_t v; std::memcpy(&v, raw, 2); return v; }
      case PlyType::UInt16: { std::uint16_t v; std::memcpy(&v, raw, 2); return v; }
      case PlyType::Int32: { std::int32_t v; std::memcpy(&v, raw, 4); return v; }
      case PlyType::UInt32: { std::uint32_t v; std::memcpy(&v, raw, 4); return v; }
      case PlyType::Float32: { float v; std::memcpy(&v, raw, 4); return v; }
      case PlyType::Float64: { double v; std::memcpy(&v, raw, 8); return v; }
    }
    return 0;
  }

  // Source line of the value just read (ASCII), 0 for binary files.
  std::size_t line() const {
    return encoding_ == Encoding::Ascii ? header_lines_ + text_.line_number() : 0;
  }

 private:
  [[noreturn]] void truncated(const Element& element, std::uint64_t instance) const {
    const std::string what = "truncated " + std::string(encoding_ == Encoding::Ascii ? "" : "binary ") +
                             "PLY: the header promises " + std::to_string(element.count) + " " + element.name +
                             " elements, the data ends inside number " + std::to_string(instance);
    fail(Error::Kind::UnreadableInput, file_, encoding_ == Encoding::Ascii ? 0 : 0,
         encoding_ == Encoding::Ascii ? what : what + " (at byte " + std::to_string(header_bytes_ + pos_) + ")");
  }

  Encoding encoding_;
  LineCursor text_;
  std::string_view body_;
  std::string file_;
  std::size_t header_lines_;
  std::size_t header_bytes_;
  std::size_t pos_ = 0;
};

}  // namespace

SurfaceMesh parse_ply(std::string_view bytes, const std::string& file) {
  // The header is text up to and including the line "end_header".
  LineCursor header(bytes, file, false);
  if (!header.next_nonempty() || header.token() != "ply") {
    fail(Error::Kind::UnreadableInput, file, 1, "not a PLY file: the first line must be 'ply'");
  }
  Encoding encoding = Encoding::Ascii;
  bool have_format = false, ended = false;
  std::vector<Element> elements;
  SurfaceMesh mesh;
  std::vector<std::pair<std::int64_t, std::string>> region_comments;
  while (!ended && header.next_nonempty()) {
    const std::string_view keyword = header.token();
    if (keyword == "format") {
      const std::string_view format = header.require_token("a format");
      if (format == "ascii") encoding = Encoding::Ascii;
      else if (format == "binary_little_endian") encoding = Encoding::BinaryLittle;
      else if (format == "binary_big_endian") encoding = Encoding::BinaryBig;
      else header.fail(Error::Kind::UnreadableInput, "unknown PLY format " + quote(format));
      have_format = true;
    } else if (keyword == "element") {
      Element e;
      e.name = std::string(header.require_token("an element name"));
      const std::int64_t count = header.require_int("an element count");
      if (count < 0) header.fail(Error::Kind::UnreadableInput, "negative element count");
      e.count = static_cast<std::uint64_t>(count);
      elements.push_back(std::move(e));
    } else if (keyword == "property") {
      if (elements.empty()) header.fail(Error::Kind::UnreadableInput, "'property' before any 'element'");
      Property p;
      std::string_view type = header.require_token("a property type");
      if (type == "list") {
        p.is_list = true;
        if (!parse_type(header.require_token("a list count type"), p.count_type)) {
          header.fail(Error::Kind::UnreadableInput, "unknown PLY list count type");
        }
        type = header.require_token("a list item type");
      }
      if (!parse_type(type, p.type)) header.fail(Error::Kind::UnreadableInput, "unknown PLY property type " + quote(type));
      p.name = std::string(header.require_token("a property name"));
      elements.back().properties.push_back(std::move(p));
    } else if (keyword == "comment") {
      // Region names written by this library: "comment vorocrust region INDEX NAME".
      if (header.token() == "vorocrust" && header.token() == "region") {
        std::int64_t index = 0;
        const std::string_view tok = header.token();
        if (parse_int(tok, index)) region_comments.emplace_back(index, std::string(header.rest_of_line()));
      }
    } else if (keyword == "end_header") {
      ended = true;
    } else if (keyword != "obj_info") {
      header.fail(Error::Kind::UnreadableInput, "unexpected " + quote(keyword) + " in the PLY header");
    }
  }
  if (!ended) fail(Error::Kind::UnreadableInput, file, header.line_number(), "truncated PLY: no 'end_header' line");
  if (!have_format) fail(Error::Kind::UnreadableInput, file, header.line_number(), "PLY header has no 'format' line");

  const std::size_t body_offset = header.offset();
  BodyReader body(bytes.substr(body_offset), encoding, file, header.line_number(), body_offset);
  mesh.groups.push_back({std::filesystem::path(file).stem().string(), file});
  std::vector<std::uint32_t> vertex_lines;
  std::vector<RegionPair> regions;
  bool labelled = false;
  std::uint64_t vertex_count = 0;
  PolygonBuffer polygon;
  for (const Element& e : elements) {
    const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
    int xyz[3] = {-1, -1, -1}, indices = -1, back = -1, front = -1;
    for (std::size_t k = 0; k < e.properties.size(); ++k) {
      const std::string& n = e.properties[k].name;
      const int ki = static_cast<int>(k);
      if (n == "x") xyz[0] = ki;
      if (n == "y") xyz[1] = ki;
      if (n == "z") xyz[2] = ki;
      if ((n == "vertex_indices" || n == "vertex_index") && e.properties[k].is_list) indices = ki;
      if (n == "back_region" && !e.properties[k].is_list) back = ki;
      if (n == "front_region" && !e.properties[k].is_list) front = ki;
    }
    if (is_vertex && (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0)) {
      fail(Error::Kind::UnreadableInput, file, 0, "PLY vertex element lacks an x, y or z property");
    }
    if (is_face && indices < 0) fail(Error::Kind::UnreadableInput, file, 0, "PLY face element lacks a vertex_indices list");
    // Every record of an element with properties takes a byte of the file at least, so a count
    // beyond the file's size is refused before anything is reserved; a record without any takes
    // none and is skipped (counting 444 million of them took the fuzzer's whole timeout).
    if (e.properties.empty()) continue;
    if (e.count > bytes.size()) {
      fail(Error::Kind::UnreadableInput, file, 0,
           "the header promises more '" + e.name + "' elements (" + std::to_string(e.count) + ") than the file can hold");
    }
    if (is_vertex) {
      vertex_count = e.count;
      mesh.vertices.reserve(e.count);
    }
    labelled = labelled || (is_face && back >= 0 && front >= 0);
    for (std::uint64_t i = 0; i < e.count; ++i) {
      double coords[3] = {0, 0, 0};
      RegionPair pair;
      polygon.clear();
      std::size_t first_line = 0;
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const Property& p = e.properties[k];
        const int ki = static_cast<int>(k);
        if (!p.is_list) {
          const double value = body.read(p.type, e, i);
          if (k == 0) first_line = body.line();
          for (int c = 0; c < 3; ++c) if (ki == xyz[c]) coords[c] = value;
          if (ki == back || ki == front) {
            // Checked before the cast, which is undefined for a value beyond the integers'.
            if (!(value >= -1 && value <= 65535)) {
              fail(Error::Kind::UnreadableInput, file, body.line(),
                   "face " + std::to_string(i) + " has a region label outside -1..65535");
            }
            (ki == back ? pair.back : pair.front) = static_cast<std::int32_t>(value);
          }
          continue;
        }
        const double n = body.read(p.count_type, e, i);
        if (k == 0) first_line = body.line();
        if (n < 0 || n != std::floor(n) || n > 1e6) {
          fail(Error::Kind::UnreadableInput, file, body.line(), "invalid list length " + std::to_string(n) + " in element '" + e.name + "' " + std::to_string(i));
        }
        for (std::size_t j = 0; j < static_cast<std::size_t>(n); ++j) {
          const double value = body.read(p.type, e, i);
          if (ki != indices) continue;
          if (value < 0 || value != std::floor(value) || value >= static_cast<double>(vertex_count)) {
            fail(Error::Kind::UnreadableInput, file, body.line(),
                 "face " + std::to_string(i) + " refers to vertex " + index_text(value) +
                     " but the file has " + std::to_string(vertex_count) + " vertices (0-based)");
          }
          polygon.push_back(static_cast<Index>(value));
        }
      }
      if (is_vertex) {
        mesh.vertices.emplace_back(coords[0], coords[1], coords[2]);
        vertex_lines.push_back(static_cast<std::uint32_t>(first_line));
      } else if (is_face) {
        if (polygon.size() < 3) {
          fail(Error::Kind::UnreadableInput, file, first_line,
               "face " + std::to_string(i) + " needs at least 3 corners, it has " + std::to_string(polygon.size()));
        }
        const std::size_t before = mesh.triangles.size();
        add_polygon(mesh, polygon, 0, static_cast<std::uint32_t>(first_line), file);
        regions.insert(regions.end(), mesh.triangles.size() - before, pair);
      }
    }
  }
  if (labelled) {
    std::int32_t max_region = -1;
    for (const RegionPair& r : regions) max_region = std::max({max_region, r.back, r.front});
    mesh.region_names.resize(static_cast<std::size_t>(max_region + 1));
    for (std::size_t r = 0; r < mesh.region_names.size(); ++r) mesh.region_names[r] = "region" + std::to_string(r);
    for (const auto& [index, name] : region_comments) {
      if (index >= 0 && static_cast<std::size_t>(index) < mesh.region_names.size()) mesh.region_names[index] = name;
    }
    mesh.face_regions = std::move(regions);
  }
  check_parsed_mesh(mesh, file, vertex_lines);
  return mesh;
}

}  // namespace vorocrust::io
