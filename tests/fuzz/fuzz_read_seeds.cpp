// seeds.csv over any bytes, as `vorocrust cells` reads it.
#include "fuzz_input.hpp"
#include "vorocrust/seeds.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace vorocrust;
  const auto path = fuzz::as_file(fuzz::bytes_of(data, size), ".csv");
  return fuzz::expect_read_or_refusal([&] { read_seeds_csv(path); });
}
