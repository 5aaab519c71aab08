// check_balls/violation_log.hpp — counting violations and keeping a few as examples.
//
// Contract: add() counts every violation; it builds and keeps one only while fewer than
// max_listed are kept for that condition and, when a key (a ball) is given, no earlier example had
// that key, so the examples show different balls rather than one ball many times. Logs filled in
// parallel over consecutive chunks and merged in chunk order keep exactly the examples a single
// pass would have kept.
#pragma once

#include <cstdarg>
#include <cstdio>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "check_balls/check_balls.hpp"
#include "check_balls/strata.hpp"

namespace vorocrust::checker {

// printf into a std::string.
inline std::string format(const char* pattern, ...) __attribute__((format(printf, 1, 2)));
inline std::string format(const char* pattern, ...) {
  va_list args;
  va_start(args, pattern);
  va_list copy;
  va_copy(copy, args);
  const int n = std::vsnprintf(nullptr, 0, pattern, copy);
  va_end(copy);
  std::string text(n > 0 ? static_cast<std::size_t>(n) : 0, '\0');
  if (n > 0) std::vsnprintf(text.data(), text.size() + 1, pattern, args);
  va_end(args);
  return text;
}

inline std::string describe(const Point& x) { return format("(%.10g, %.10g, %.10g)", x.x(), x.y(), x.z()); }

inline std::string describe(StratumRef s) {
  if (s.index == kNone) return format("%s ?", to_string(s.type));
  return format("%s %u", to_string(s.type), s.index);
}

inline std::string describe_ball(const std::vector<CheckedBall>& balls, std::size_t i) {
  const CheckedBall& b = balls[i];
  std::string line = b.line ? format("line %zu, ", b.line) : std::string();
  return format("ball %zu (%s%s, r %.10g, at %s)", i, line.c_str(), to_string(b.type), b.radius,
                describe(b.centre).c_str());
}

class ViolationLog {
 public:
  explicit ViolationLog(std::size_t max_listed) : max_listed_(max_listed) {}

  template <class Make>
  void add(Condition condition, std::optional<std::size_t> key, Make&& make) {
    Entry& entry = entries_[static_cast<std::size_t>(condition)];
    ++entry.count;
    if (!keep(entry, key)) return;
    Violation v = make();
    v.condition = condition;
    entry.examples.push_back({std::move(v), key});
  }

  // Appends a log of what came after this one.
  void merge(ViolationLog&& later) {
    for (std::size_t c = 0; c < kConditionCount; ++c) {
      Entry& entry = entries_[c];
      entry.count += later.entries_[c].count;
      for (auto& example : later.entries_[c].examples) {
        if (keep(entry, example.key)) entry.examples.push_back(std::move(example));
      }
    }
  }

  void write_to(BallCheckReport& report) const {
    for (std::size_t c = 0; c < kConditionCount; ++c) {
      ConditionResult& result = report.conditions[c];
      result.count += entries_[c].count;
      for (const auto& example : entries_[c].examples) result.examples.push_back(example.violation);
    }
  }

 private:
  struct Example {
    Violation violation;
    std::optional<std::size_t> key;
  };
  struct Entry {
    std::size_t count = 0;
    std::vector<Example> examples;
    std::set<std::size_t> keys;
  };

  bool keep(Entry& entry, std::optional<std::size_t> key) const {
    if (entry.examples.size() >= max_listed_ || (key && entry.keys.count(*key))) return false;
    if (key) entry.keys.insert(*key);
    return true;
  }

  std::size_t max_listed_;
  Entry entries_[kConditionCount];
};

}  // namespace vorocrust::checker
