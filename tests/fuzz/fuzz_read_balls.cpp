// balls.csv over any bytes, as `vorocrust check-balls` reads it.
#include "check_balls/check_balls.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace vorocrust;
  const auto path = fuzz::as_file(fuzz::bytes_of(data, size), ".csv");
  return fuzz::expect_read_or_refusal([&] { checker::read_balls_csv(path); });
}
