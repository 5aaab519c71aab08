#include "vorocrust/error.hpp"

namespace vorocrust {
namespace {

std::string with_location(const std::string& message, const Error::Location& where) {
  std::string text;
  if (!where.file.empty()) {
    text.append(where.file);
    if (where.line > 0) text.append(":").append(std::to_string(where.line));
    text.append(": ");
  }
  text.append(message);
  return text;
}

}  // namespace

Error::Error(Kind kind, std::string message, Location where)
    : std::runtime_error(with_location(message, where)),
      kind_(kind),
      message_(std::move(message)),
      where_(std::move(where)) {}

const char* to_string(Error::Kind kind) noexcept {
  switch (kind) {
    case Error::Kind::Usage: return "usage error";
    case Error::Kind::UnreadableInput: return "unreadable input";
    case Error::Kind::InvalidGeometry: return "invalid geometry";
    case Error::Kind::Output: return "output error";
    case Error::Kind::Cancelled: return "cancelled";
    case Error::Kind::NotImplemented: return "not yet implemented";
    case Error::Kind::Internal: return "internal error";
  }
  return "internal error";
}

}  // namespace vorocrust
