// Paths to the shared models and the test data, for every test.
#pragma once

#include <filesystem>
#include <string>
#include <unistd.h>

namespace vorocrust::test {

inline std::filesystem::path model(const std::string& name) {
  return std::filesystem::path(VOROCRUST_MODELS_DIR) / name;
}

inline std::filesystem::path data(const std::string& name) {
  return std::filesystem::path(VOROCRUST_TEST_DATA_DIR) / name;
}

// A fresh, empty folder under the system's temporary folder, removed at destruction.
class TempDir {
 public:
  explicit TempDir(const std::string& tag);
  ~TempDir();
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

inline TempDir::TempDir(const std::string& tag) {
  static int counter = 0;
  path_ = std::filesystem::temp_directory_path() /
          ("vorocrust-test-" + tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

inline TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace vorocrust::test
