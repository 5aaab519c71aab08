// A reader of the PNG files report.html embeds (8-bit RGB, no filter, no interlace), for tests:
// it checks the signature, every chunk's CRC and the header, and gives the pixels. Failures are
// gtest failures (ADD_FAILURE), leaving the result empty.
#pragma once

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <string>
#include <vector>

namespace vorocrust::test {

struct DecodedPng {
  int width = 0, height = 0;
  std::vector<std::string> chunks;  // their types, in order
  std::vector<std::uint8_t> rgb;    // row by row, top first
};

inline std::uint32_t png_u32(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<std::uint8_t>(s[at + i]);
  return v;
}

inline DecodedPng decode_png(const std::string& png) {
  DecodedPng out;
  if (png.size() < 8 || png.substr(0, 8) != std::string("\x89PNG\r\n\x1a\n", 8)) {
    ADD_FAILURE() << "no PNG signature";
    return out;
  }
  std::string idat;
  std::size_t at = 8;
  while (at + 12 <= png.size()) {
    const std::uint32_t length = png_u32(png, at);
    if (at + 12 + length > png.size()) break;
    const std::string typed = png.substr(at + 4, 4 + length);
    if (png_u32(png, at + 8 + length) != crc32(0L, reinterpret_cast<const Bytef*>(typed.data()), static_cast<uInt>(typed.size()))) {
      ADD_FAILURE() << "bad CRC in chunk " << typed.substr(0, 4);
      return out;
    }
    const std::string type = typed.substr(0, 4), data = typed.substr(4);
    if (type == "IHDR") {
      out.width = static_cast<int>(png_u32(data, 0));
      out.height = static_cast<int>(png_u32(data, 4));
      EXPECT_EQ(data.substr(8), std::string("\x08\x02\x00\x00\x00", 5)) << "not 8-bit RGB without interlace";
    }
    if (type == "IDAT") idat += data;
    out.chunks.push_back(type);
    at += 12 + length;
  }
  if (at != png.size()) ADD_FAILURE() << "trailing or truncated chunk at byte " << at;
  const std::size_t row = 1 + 3 * static_cast<std::size_t>(out.width);
  std::string raw(row * static_cast<std::size_t>(out.height), '\0');
  uLongf size = static_cast<uLongf>(raw.size());
  if (uncompress(reinterpret_cast<Bytef*>(raw.data()), &size, reinterpret_cast<const Bytef*>(idat.data()),
                 static_cast<uLong>(idat.size())) != Z_OK ||
      size != raw.size()) {
    ADD_FAILURE() << "IDAT does not inflate to " << raw.size() << " bytes";
    return out;
  }
  for (std::size_t y = 0; y < static_cast<std::size_t>(out.height); ++y) {
    EXPECT_EQ(raw[y * row], '\0') << "row " << y << " filtered";
    out.rgb.insert(out.rgb.end(), raw.begin() + static_cast<std::ptrdiff_t>(y * row + 1),
                   raw.begin() + static_cast<std::ptrdiff_t>((y + 1) * row));
  }
  return out;
}

// A base64 decoder for the pictures' data URIs (RFC 4648 alphabet, padded).
inline std::string decode_base64(const std::string& text) {
  std::string out;
  std::uint32_t bits = 0;
  int count = 0;
  for (char c : text) {
    int v;
    if (c >= 'A' && c <= 'Z') v = c - 'A';
    else if (c >= 'a' && c <= 'z') v = c - 'a' + 26;
    else if (c >= '0' && c <= '9') v = c - '0' + 52;
    else if (c == '+') v = 62;
    else if (c == '/') v = 63;
    else break;  // '=' or the end of the URI
    bits = (bits << 6) | static_cast<std::uint32_t>(v);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out += static_cast<char>((bits >> count) & 0xff);
    }
  }
  return out;
}

}  // namespace vorocrust::test
