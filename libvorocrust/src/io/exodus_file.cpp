#include "io/exodus_file.hpp"

#include <exodusII.h>

#include <utility>

namespace vorocrust::io {

namespace {

// Exodus prints every error to stderr unless told not to; the library reports through Error.
void quiet() { ex_opts(0); }

std::string library_message() {
  const char *message = nullptr, *function = nullptr;
  int code = 0;
  ex_get_err(&message, &function, &code);
  return message != nullptr && *message != '\0' ? std::string(message) : "error " + std::to_string(code);
}

}  // namespace

ExodusFile ExodusFile::create(const std::filesystem::path& path, const std::filesystem::path& shown) {
  quiet();
  int word = sizeof(double), io_word = sizeof(double);
  const int id = ex_create(path.c_str(), EX_CLOBBER | EX_LARGE_MODEL, &word, &io_word);
  if (id < 0) throw Error(Error::Kind::Output, "cannot create the Exodus file: " + library_message(), {.file = shown.string()});
  // Names as long as the regions' (the default keeps 32 characters).
  ex_set_option(id, EX_OPT_MAX_NAME_LENGTH, 80);
  return ExodusFile(id, shown.string(), Error::Kind::Output);
}

ExodusFile ExodusFile::open(const std::filesystem::path& path) {
  quiet();
  int word = sizeof(double), io_word = 0;
  float version = 0;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw Error(Error::Kind::UnreadableInput, "no such file", {.file = path.string()});
  }
  const int id = ex_open(path.c_str(), EX_READ, &word, &io_word, &version);
  if (id < 0) {
    throw Error(Error::Kind::UnreadableInput, "not an Exodus II file: " + library_message(), {.file = path.string()});
  }
  ex_set_option(id, EX_OPT_MAX_NAME_LENGTH, 80);
  return ExodusFile(id, path.string(), Error::Kind::UnreadableInput);
}

ExodusFile::ExodusFile(ExodusFile&& other) noexcept
    : id_(std::exchange(other.id_, -1)), shown_(std::move(other.shown_)), kind_(other.kind_) {}

ExodusFile::~ExodusFile() {
  if (id_ >= 0) ex_close(id_);
}

void ExodusFile::check(int status, const std::string& what) const {
  if (status < 0) {
    throw Error(kind_, (kind_ == Error::Kind::Output ? "cannot write " : "cannot read ") + what + ": " + library_message(),
                {.file = shown_});
  }
}

void ExodusFile::close() {
  const int id = std::exchange(id_, -1);
  check(ex_close(id), "the end of the file");
}

}  // namespace vorocrust::io
