#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include "io/byte_source.hpp"
#include "vorocrust/seeds.hpp"

namespace vorocrust {
namespace {

constexpr std::string_view kHeader = "x,y,z,label,radius,kind";
constexpr const char* kFieldNames[6] = {"x", "y", "z", "label", "radius", "kind"};

Seed parse_seed(io::LineCursor& in, std::string_view line) {
  std::array<std::string_view, 6> field;
  std::size_t count = 0;
  for (std::size_t start = 0;; ++count) {
    const std::size_t comma = line.find(',', start);
    if (count < field.size()) field[count] = line.substr(start, comma == std::string_view::npos ? comma : comma - start);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  for (std::size_t k = 0; k < std::min(count + 1, field.size()); ++k) {
    while (!field[k].empty() && (field[k].front() == ' ' || field[k].front() == '\t')) field[k].remove_prefix(1);
    while (!field[k].empty() && (field[k].back() == ' ' || field[k].back() == '\t')) field[k].remove_suffix(1);
  }
  if (++count != field.size()) {
    in.fail(Error::Kind::UnreadableInput, "a seed has 6 comma-separated fields (" + std::string(kHeader) + "), this line " +
                                              std::to_string(count));
  }
  Seed s;
  for (int d = 0; d < 3; ++d) {
    if (!io::parse_double(field[d], s.position[d]) || !std::isfinite(s.position[d])) {
      in.fail(Error::Kind::UnreadableInput, std::string(kFieldNames[d]) + " is not a finite number: " + io::quote(field[d]));
    }
  }
  std::int64_t label = 0;
  if (!io::parse_int(field[3], label) || label < std::numeric_limits<std::int32_t>::min() ||
      label > std::numeric_limits<std::int32_t>::max()) {
    in.fail(Error::Kind::UnreadableInput, "label is not a 32-bit integer: " + io::quote(field[3]));
  }
  s.region = static_cast<std::int32_t>(label);
  if (!io::parse_double(field[4], s.radius) || !std::isfinite(s.radius) || s.radius < 0) {
    in.fail(Error::Kind::UnreadableInput, "radius is not a finite number >= 0: " + io::quote(field[4]));
  }
  if (const std::optional<SeedKind> kind = seed_kind_named(field[5])) {
    s.kind = *kind;
    return s;
  }
  in.fail(Error::Kind::UnreadableInput, "kind is not " + seed_kind_names() + ": " + io::quote(field[5]));
}

}  // namespace

std::vector<Seed> read_seeds_csv(const std::filesystem::path& path) {
  const std::string bytes = io::read_file_bytes(path);
  io::LineCursor in(bytes, path.string(), false);
  if (!in.next_nonempty()) io::fail(Error::Kind::UnreadableInput, path.string(), 0, "empty: no header line " + std::string(kHeader));
  if (in.rest_of_line() != kHeader) {
    in.fail(Error::Kind::UnreadableInput, "the header line is not " + std::string(kHeader) + ": " + io::quote(in.rest_of_line()));
  }
  std::vector<Seed> seeds;
  while (in.next_nonempty()) seeds.push_back(parse_seed(in, in.rest_of_line()));
  return seeds;
}

}  // namespace vorocrust
