// printf-style text in the "C" locale.
#include "core/c_format.hpp"

#include <clocale>
#include <cstdarg>
#include <cstdio>
#include <locale.h>

namespace vorocrust {

std::string c_format(const char* format, ...) {
  // uselocale changes the calling thread's locale only, and is undone before returning.
  static const locale_t c_locale = newlocale(LC_ALL_MASK, "C", static_cast<locale_t>(nullptr));
  const locale_t previous = uselocale(c_locale);
  va_list args;
  va_start(args, format);
  va_list again;
  va_copy(again, args);
  const int length = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  std::string text(length > 0 ? static_cast<std::size_t>(length) : 0, '\0');
  if (length > 0) std::vsnprintf(text.data(), text.size() + 1, format, again);
  va_end(again);
  uselocale(previous);
  return text;
}

}  // namespace vorocrust
