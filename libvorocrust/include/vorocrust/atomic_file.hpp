// vorocrust/atomic_file.hpp — writing a file so that it is either complete or absent.
//
// The content goes to a temporary file beside the target, which is renamed over the target only
// after everything was written and flushed. A failure (an exception from `write`, a full disk)
// removes the temporary file and throws Error(Output); an earlier file at `path` stays intact.
// The stream `write` gets is in the classic locale, whatever locale the host application set:
// numbers read the same on every machine.
//
// write_path_atomically serves writers that open the file by name themselves (netCDF for Exodus
// II): `write` creates the temporary path it is given, which is then renamed over `path`, or
// removed when `write` throws.
#pragma once

#include "vorocrust/api.hpp"

#include <filesystem>
#include <functional>
#include <ostream>
#include <string_view>

namespace vorocrust {

VOROCRUST_API void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);
VOROCRUST_API void write_file_atomically(const std::filesystem::path& path, std::string_view content);
VOROCRUST_API void write_path_atomically(const std::filesystem::path& path,
                                         const std::function<void(const std::filesystem::path& temp)>& write);

}  // namespace vorocrust
