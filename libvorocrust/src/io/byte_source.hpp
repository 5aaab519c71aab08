// Internal: whole-file reading and a line/token cursor that knows where it is, so that every
// parse error names its file and line. Parsing is bounds-checked on every token: broken files
// end in an Error, never in a read past the buffer.
#pragma once

#include <charconv>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "vorocrust/error.hpp"

namespace vorocrust::io {

// The file's bytes; throws Error(UnreadableInput) when it is missing, a directory or unreadable.
std::string read_file_bytes(const std::filesystem::path& path);

[[noreturn]] void fail(Error::Kind kind, const std::string& file, std::size_t line,
                       const std::string& message);

// Walks text line by line; `#` starts a comment when `hash_comments` is set.
class LineCursor {
 public:
  LineCursor(std::string_view text, std::string file, bool hash_comments = true)
      : text_(text), file_(std::move(file)), hash_comments_(hash_comments) {}

  // Advances to the next line that has a token; false at the end of the text.
  bool next_nonempty();
  // The next whitespace-separated token of the current line, empty when there is none.
  std::string_view token();
  // Like token(), but a missing token is an error naming `what`.
  std::string_view require_token(const char* what);
  std::string_view rest_of_line();  // the untokenized remainder, trimmed

  double require_double(const char* what);
  std::int64_t require_int(const char* what);

  std::size_t line_number() const { return line_no_; }
  const std::string& file() const { return file_; }
  std::size_t offset() const { return pos_; }
  std::string_view remaining_text() const { return text_.substr(pos_); }

  [[noreturn]] void fail(Error::Kind kind, const std::string& message) const {
    io::fail(kind, file_, line_no_, message);
  }

 private:
  std::string_view text_;
  std::string file_;
  bool hash_comments_;
  std::size_t pos_ = 0;
  std::size_t line_no_ = 0;
  std::string_view line_;
};

// Parses a whole token as a number; false when the token is not exactly one number.
bool parse_double(std::string_view token, double& value);
bool parse_int(std::string_view token, std::int64_t& value);

// "'abc'" with unprintable bytes escaped and long tokens shortened, for messages.
std::string quote(std::string_view token);

}  // namespace vorocrust::io
