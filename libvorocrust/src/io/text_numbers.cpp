#include "io/text_numbers.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "vorocrust/error.hpp"

namespace vorocrust::io {

void append_number(std::string& out, double x) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
  out.append(buffer, ec == std::errc{} ? end : buffer);
}

void append_number(std::string& out, long long n) {
  char buffer[24];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, n);
  out.append(buffer, ec == std::errc{} ? end : buffer);
}

std::string fortran_e(double x, int width) {
  if (std::isfinite(x)) {
    // The fewest characters besides the digits after the point: "d.", "e+dd" and a sign. Fewer
    // digits are tried where rounding or a wider exponent needs them.
    const int overhead = 6 + (std::signbit(x) ? 1 : 0);
    for (int digits = std::max(width - overhead, 0); digits >= 0; --digits) {
      char buffer[48];
      const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::scientific, digits);
      if (ec != std::errc{}) continue;
      const int length = static_cast<int>(end - buffer);
      if (length > width) continue;
      std::string field(static_cast<std::size_t>(width - length), ' ');
      for (const char* c = buffer; c != end; ++c) field += *c == 'e' ? 'E' : *c;
      return field;
    }
  }
  throw Error(Error::Kind::Output, "the number " + std::to_string(x) + " does not fit a field of " +
                                       std::to_string(width) + " characters");
}

}  // namespace vorocrust::io
