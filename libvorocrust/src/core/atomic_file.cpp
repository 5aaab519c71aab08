#include "vorocrust/atomic_file.hpp"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <locale>
#include <unistd.h>

#include "vorocrust/error.hpp"

namespace vorocrust {

void write_path_atomically(const std::filesystem::path& path,
                           const std::function<void(const std::filesystem::path& temp)>& write) {
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path parent = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  // Appended piece by piece: GCC 12 warns of an overlap (-Wrestrict) in "." + string.
  std::string name = ".";
  name += path.filename().string();
  name += ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  const std::filesystem::path temp = parent / name;
  try {
    write(temp);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw;
  }
  std::error_code ec;
  std::filesystem::rename(temp, path, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw Error(Error::Kind::Output, "cannot write: " + ec.message(), {.file = path.string()});
  }
}

void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write) {
  write_path_atomically(path, [&](const std::filesystem::path& temp) {
    const auto fail = [&](const std::string& why) {
      throw Error(Error::Kind::Output, "cannot write: " + why, {.file = path.string()});
    };
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) fail(std::strerror(errno));
    out.imbue(std::locale::classic());
    write(out);
    out.flush();
    if (!out) fail("write failed (disk full?)");
  });
}

void write_file_atomically(const std::filesystem::path& path, std::string_view content) {
  write_file_atomically(path, [&](std::ostream& out) { out.write(content.data(), static_cast<std::streamsize>(content.size())); });
}

}  // namespace vorocrust
