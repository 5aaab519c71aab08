// vorocrust/error.hpp — how the library reports failure.
//
// Every failure leaves the library as a vorocrust::Error carrying a Kind (which class of problem)
// and, where known, the file, line and face it concerns. The library never calls abort or exit:
// a host application (MeshLab, FreeCAD) survives every bad input.
#pragma once

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>

#include "vorocrust/api.hpp"

namespace vorocrust {

// Where a problem lies: the file, its line, and the face of the merged mesh, as far as known.
struct VOROCRUST_API ErrorLocation {
  std::string file;                // empty when the problem is not tied to a file
  std::size_t line = 0;            // 1-based; 0 when unknown (binary formats)
  std::optional<std::size_t> face; // 0-based index in the merged mesh
  std::string option;              // the option at fault, by its name in options.hpp's table
};

class VOROCRUST_API Error : public std::runtime_error {
 public:
  using Location = ErrorLocation;

  enum class Kind {
    Usage,            // an option or argument the caller got wrong
    UnreadableInput,  // missing file, unknown format, malformed or truncated content
    InvalidGeometry,  // readable, but not a mesh the algorithm accepts (NaN, empty, ...)
    Output,           // a result could not be written
    Cancelled,        // the progress callback asked to stop
    NotImplemented,   // a stage that does not exist yet
    Internal,         // a bug: an invariant of the library did not hold
  };

  Error(Kind kind, std::string message, Location where = {});

  Kind kind() const noexcept { return kind_; }
  const Location& where() const noexcept { return where_; }
  // The message alone, without the location prefix that what() carries.
  const std::string& message() const noexcept { return message_; }

 private:
  Kind kind_;
  std::string message_;
  Location where_;
};

// "unreadable input", "invalid geometry", ... for messages and JSON.
VOROCRUST_API const char* to_string(Error::Kind kind) noexcept;

}  // namespace vorocrust
