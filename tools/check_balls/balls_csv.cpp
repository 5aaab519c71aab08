#include <charconv>
#include <cmath>
#include <fstream>
#include <string_view>

#include "check_balls/check_balls.hpp"
#include "check_balls/violation_log.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust::checker {
namespace {

constexpr std::string_view kHeader[] = {"x", "y", "z", "radius", "stratum_type", "stratum_index"};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> fields;
  while (true) {
    const std::size_t comma = line.find(',');
    fields.push_back(trim(line.substr(0, comma)));
    if (comma == std::string_view::npos) return fields;
    line.remove_prefix(comma + 1);
  }
}

class LineError {
 public:
  LineError(const std::filesystem::path& path, std::size_t line) : path_(path), line_(line) {}
  [[noreturn]] void operator()(const std::string& message) const {
    throw Error(Error::Kind::UnreadableInput, message, {path_.string(), line_, std::nullopt});
  }

 private:
  const std::filesystem::path& path_;
  std::size_t line_;
};

double parse_number(std::string_view field, const char* name, const LineError& fail) {
  double value = 0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (ec != std::errc() || end != field.data() + field.size() || field.empty()) {
    fail(format("%s '%.*s' is not a number", name, static_cast<int>(field.size()), field.data()));
  }
  if (!std::isfinite(value)) fail(format("%s is not finite", name));
  return value;
}

}  // namespace

std::vector<CheckedBall> read_balls_csv(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(Error::Kind::UnreadableInput, "cannot open the balls file", {path.string(), 0, std::nullopt});
  std::vector<CheckedBall> balls;
  std::string text;
  std::size_t line = 0;
  bool header = false;
  while (std::getline(in, text)) {
    ++line;
    const LineError fail(path, line);
    const std::string_view content = trim(text);
    if (content.empty()) continue;
    const std::vector<std::string_view> fields = split(content);
    if (!header) {
      if (!std::equal(fields.begin(), fields.end(), std::begin(kHeader), std::end(kHeader))) {
        fail("expected the header 'x,y,z,radius,stratum_type,stratum_index'");
      }
      header = true;
      continue;
    }
    if (fields.size() != 6) fail(format("expected 6 comma-separated fields, found %zu", fields.size()));
    CheckedBall ball;
    ball.line = line;
    ball.centre = {parse_number(fields[0], "x", fail), parse_number(fields[1], "y", fail),
                   parse_number(fields[2], "z", fail)};
    ball.radius = parse_number(fields[3], "radius", fail);
    if (!(ball.radius > 0)) fail(format("radius %g is not positive", ball.radius));
    if (fields[4] == "corner") {
      ball.type = StratumType::Corner;
    } else if (fields[4] == "crease") {
      ball.type = StratumType::Crease;
    } else if (fields[4] == "patch") {
      ball.type = StratumType::Patch;
    } else {
      fail(format("stratum_type '%.*s' is none of corner, crease, patch", static_cast<int>(fields[4].size()),
                  fields[4].data()));
    }
    const std::string_view index = fields[5];
    const auto [end, ec] = std::from_chars(index.data(), index.data() + index.size(), ball.stratum_index);
    if (ec != std::errc() || end != index.data() + index.size() || index.empty()) {
      fail(format("stratum_index '%.*s' is not a non-negative integer", static_cast<int>(index.size()), index.data()));
    }
    balls.push_back(ball);
  }
  if (in.bad()) throw Error(Error::Kind::UnreadableInput, "read error", {path.string(), line, std::nullopt});
  if (!header) {
    throw Error(Error::Kind::UnreadableInput, "empty file, expected a header line", {path.string(), 1, std::nullopt});
  }
  return balls;
}

void write_balls_csv(const std::filesystem::path& path, const std::vector<CheckedBall>& balls) {
  std::ofstream out(path, std::ios::binary);
  out << "x,y,z,radius,stratum_type,stratum_index\n";
  for (const CheckedBall& b : balls) {
    out << format("%.17g,%.17g,%.17g,%.17g,%s,%llu\n", b.centre.x(), b.centre.y(), b.centre.z(), b.radius,
                  to_string(b.type), static_cast<unsigned long long>(b.stratum_index));
  }
  if (!out) throw Error(Error::Kind::Output, "cannot write the balls file", {path.string(), 0, std::nullopt});
}

}  // namespace vorocrust::checker
