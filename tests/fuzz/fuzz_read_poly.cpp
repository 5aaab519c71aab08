// A 2D domain over any bytes (Triangle's .poly), read and prepared as mesh2d prepares it:
// crossings split, degenerate segments named.
#include "fuzz_input.hpp"
#include "vorocrust/plane.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace vorocrust;
  const auto path = fuzz::as_file(fuzz::bytes_of(data, size), ".poly");
  return fuzz::expect_read_or_refusal([&] {
    const PlanarDomain domain = prepare_planar_domain(read_planar_domain(path));
    for (const auto& s : domain.segments) {
      if (s[0] >= domain.points.size() || s[1] >= domain.points.size() || s[0] == s[1]) __builtin_trap();
    }
  });
}
