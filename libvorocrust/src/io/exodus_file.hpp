// Internal: an open Exodus II file, closed when it goes, whose calls throw Error naming the file
// and the part of the mesh they failed on; and the names the writer and the reader share.
#pragma once

#include <array>
#include <filesystem>
#include <string>

#include "vorocrust/error.hpp"

namespace vorocrust::io {

class ExodusFile {
 public:
  static constexpr int kFaceBlock = 1;
  static constexpr const char* kFromRegion = "FROM_REGION";
  static constexpr const char* kToRegion = "TO_REGION";
  static constexpr std::array<const char*, 5> kCellVariables = {"seed", "sitex", "sitey", "sitez", "volume"};

  // A new file at `path` (replacing one there), reported in errors as `shown`: the writer creates
  // a temporary file and names the target. Throws Error(Output).
  static ExodusFile create(const std::filesystem::path& path, const std::filesystem::path& shown);
  // An existing file, for reading. Throws Error(UnreadableInput).
  static ExodusFile open(const std::filesystem::path& path);

  ExodusFile(ExodusFile&& other) noexcept;
  ExodusFile& operator=(ExodusFile&&) = delete;
  ~ExodusFile();

  int id() const { return id_; }
  // Throws Error (Output when writing, UnreadableInput when reading) naming the file and `what`
  // when `status` is negative (an Exodus error; positive statuses are warnings).
  void check(int status, const std::string& what) const;
  // Closes the file, throwing as check() does when the library cannot finish it.
  void close();

 private:
  ExodusFile(int id, std::string shown, Error::Kind kind) : id_(id), shown_(std::move(shown)), kind_(kind) {}
  int id_ = -1;
  std::string shown_;
  Error::Kind kind_;
};

}  // namespace vorocrust::io
