// A sizing file over any bytes, read and queried as the refinement queries it.
#include "fuzz_input.hpp"
#include "refinement/sizing_field.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace vorocrust;
  const auto path = fuzz::as_file(fuzz::bytes_of(data, size), ".txt");
  return fuzz::expect_read_or_refusal([&] {
    const SizingField sizing(1.0, path);
    const double h = sizing(Point(0.25, -0.5, 1.0));
    if (!(h > 0) || h > 1.0) __builtin_trap();  // positive, at most the largest size
  });
}
