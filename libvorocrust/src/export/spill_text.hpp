// Internal: the big lists of a mesh file go out a block at a time.
//
// spill(out, text) writes `text` to `out` and empties it once it holds a megabyte or more;
// spill(out, text, 0) writes whatever it holds. A writer appends its lines to one string and
// spills after each: the file is never whole in memory, which at ten million cells would be
// gigabytes of text beside the mesh.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>

namespace vorocrust::io {

inline void spill(std::ostream& out, std::string& text, std::size_t at = std::size_t{1} << 20) {
  if (text.size() < at) return;
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  text.clear();
}

}  // namespace vorocrust::io
