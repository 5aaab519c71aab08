// Fuzz targets: what each reader must do with any bytes at all. A reader either returns what its
// contract promises or throws vorocrust::Error naming the file and line; anything else (another
// exception, a crash, a sanitizer report, a hang, memory beyond what the bytes allow) is a bug.
// Each target defines LLVMFuzzerTestOneInput; built with clang's -fsanitize=fuzzer it is a
// libFuzzer program (VOROCRUST_FUZZ), otherwise replay_main.cpp runs it over a corpus (CTest).
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "vorocrust/error.hpp"

namespace vorocrust::fuzz {

inline std::string_view bytes_of(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// The readers of the seeds, sizing and balls files take a path, as their programs do: the bytes
// go to a file of this process's own, so the whole reading path runs.
inline std::filesystem::path as_file(std::string_view bytes, const char* extension) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("vorocrust-fuzz-" + std::to_string(::getpid()) + extension);
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return path;
}

// Runs `read`. A reader refuses only with an Error of unreadable input or invalid geometry that
// names the file; an internal error, another exception or no file named is a finding.
template <class Read>
int expect_read_or_refusal(Read&& read) {
  try {
    read();
  } catch (const Error& e) {
    const bool refusal = e.kind() == Error::Kind::UnreadableInput || e.kind() == Error::Kind::InvalidGeometry;
    if (!refusal || e.where().file.empty()) __builtin_trap();
  }
  return 0;
}

}  // namespace vorocrust::fuzz
