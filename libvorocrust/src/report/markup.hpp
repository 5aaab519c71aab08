// Text for SVG and HTML pages: numbers written the same in every locale, markup escaped, binary
// data as base64 for data: URIs (RFC 4648, with padding).
#pragma once

#include <charconv>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace vorocrust::report {

// std::to_chars ignores the locale, unlike printf and streams: a host application running in a
// locale with decimal commas still gets valid markup.
std::string locale_free_number(double x, std::chars_format format, int precision);

// `text` with &, <, > and " replaced by their entities, for element text and attribute values.
std::string escape_markup(std::string_view text);

std::string base64(std::span<const std::uint8_t> bytes);
std::string base64(std::string_view bytes);

}  // namespace vorocrust::report
