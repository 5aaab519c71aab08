// Paths to the shared models, the test data and the samples, and small helpers, for every test.
#pragma once

#include <cstddef>
#include <filesystem>
#include <numbers>
#include <string>
#include <unistd.h>

namespace vorocrust::test {

constexpr double kDegree = std::numbers::pi / 180;

// 1 - alpha: how deep a point must lie in a ball to count as deeply covered (conditions C3, C4).
constexpr double kDeep = std::numbers::sqrt3 / 2;

inline std::filesystem::path model(const std::string& name) {
  return std::filesystem::path(VOROCRUST_MODELS_DIR) / name;
}

inline std::filesystem::path data(const std::string& name) {
  return std::filesystem::path(VOROCRUST_TEST_DATA_DIR) / name;
}

// A 2D domain of samples/2d.
inline std::filesystem::path sample_2d(const std::string& name) {
  return std::filesystem::path(VOROCRUST_SAMPLES_DIR) / "2d" / name;
}

inline std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
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
