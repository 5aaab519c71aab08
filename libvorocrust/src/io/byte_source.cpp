#include "io/byte_source.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <system_error>

namespace vorocrust::io {

std::string read_file_bytes(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) {
    fail(Error::Kind::UnreadableInput, name, 0, "cannot open: no such file");
  }
  if (std::filesystem::is_directory(status)) {
    fail(Error::Kind::UnreadableInput, name, 0, "cannot open: is a directory");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    fail(Error::Kind::UnreadableInput, name, 0, std::string("cannot open: ") + std::strerror(errno));
  }
  std::string bytes;
  in.seekg(0, std::ios::end);
  const auto size = in.tellg();
  if (size < 0) fail(Error::Kind::UnreadableInput, name, 0, "cannot determine the file's size");
  bytes.resize(static_cast<std::size_t>(size));
  in.seekg(0, std::ios::beg);
  in.read(bytes.data(), size);
  if (in.gcount() != size) fail(Error::Kind::UnreadableInput, name, 0, "read failed");
  return bytes;
}

void fail(Error::Kind kind, const std::string& file, std::size_t line, const std::string& message) {
  throw Error(kind, message, {.file = file, .line = line});
}

namespace {
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
}  // namespace

bool LineCursor::next_nonempty() {
  while (pos_ < text_.size()) {
    const std::size_t end = text_.find('\n', pos_);
    const std::size_t stop = end == std::string_view::npos ? text_.size() : end;
    line_ = text_.substr(pos_, stop - pos_);
    pos_ = stop == text_.size() ? stop : stop + 1;
    ++line_no_;
    if (hash_comments_) {
      const std::size_t hash = line_.find('#');
      if (hash != std::string_view::npos) line_ = line_.substr(0, hash);
    }
    std::size_t first = 0;
    while (first < line_.size() && is_space(line_[first])) ++first;
    line_ = line_.substr(first);
    if (!line_.empty()) return true;
  }
  line_ = {};
  return false;
}

std::string_view LineCursor::token() {
  std::size_t i = 0;
  while (i < line_.size() && is_space(line_[i])) ++i;
  std::size_t j = i;
  while (j < line_.size() && !is_space(line_[j])) ++j;
  const std::string_view tok = line_.substr(i, j - i);
  line_ = line_.substr(j);
  return tok;
}

std::string_view LineCursor::require_token(const char* what) {
  const std::string_view tok = token();
  if (tok.empty()) fail(Error::Kind::UnreadableInput, std::string("expected ") + what + ", found end of line");
  return tok;
}

std::string_view LineCursor::rest_of_line() {
  std::string_view rest = line_;
  while (!rest.empty() && is_space(rest.front())) rest.remove_prefix(1);
  while (!rest.empty() && is_space(rest.back())) rest.remove_suffix(1);
  line_ = {};
  return rest;
}

double LineCursor::require_double(const char* what) {
  const std::string_view tok = require_token(what);
  double value = 0;
  if (!parse_double(tok, value)) {
    fail(Error::Kind::UnreadableInput, std::string("expected ") + what + ", found " + quote(tok));
  }
  return value;
}

std::int64_t LineCursor::require_int(const char* what) {
  const std::string_view tok = require_token(what);
  std::int64_t value = 0;
  if (!parse_int(tok, value)) {
    fail(Error::Kind::UnreadableInput, std::string("expected ") + what + ", found " + quote(tok));
  }
  return value;
}

bool parse_double(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  // Out-of-range literals (1e999) parse as a range error: report them as not finite downstream.
  if (ec == std::errc::result_out_of_range && ptr == end) {
    value = token.find('-') == 0 ? -HUGE_VAL : HUGE_VAL;
    return true;
  }
  return ec == std::errc() && ptr == end && !token.empty();
}

bool parse_int(std::string_view token, std::int64_t& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return ec == std::errc() && ptr == end && !token.empty();
}

std::string quote(std::string_view token) {
  std::string out = "'";
  const std::size_t shown = token.size() > 40 ? 40 : token.size();
  for (std::size_t i = 0; i < shown; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    if (c >= 32 && c < 127) {
      out += static_cast<char>(c);
    } else {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  if (shown < token.size()) out += "...";
  return out + "'";
}

}  // namespace vorocrust::io
