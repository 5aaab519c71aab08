// A mesh reader over any bytes, then what `vorocrust info` does with what it read: validation
// (which fixes orientation and folds in place) and the counts and measures.
// VOROCRUST_FUZZ_FORMAT names the reader: off, obj, stl or ply (one program each).
#include "fuzz_input.hpp"
#include "io/readers.hpp"
#include "vorocrust/mesh_info.hpp"
#include "vorocrust/validate.hpp"

#define VOROCRUST_FUZZ_JOIN2(a, b) a##b
#define VOROCRUST_FUZZ_JOIN(a, b) VOROCRUST_FUZZ_JOIN2(a, b)
#define VOROCRUST_FUZZ_TEXT2(a) #a
#define VOROCRUST_FUZZ_TEXT(a) VOROCRUST_FUZZ_TEXT2(a)

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace vorocrust;
  return fuzz::expect_read_or_refusal([&] {
    SurfaceMesh mesh = io::VOROCRUST_FUZZ_JOIN(parse_, VOROCRUST_FUZZ_FORMAT)(
        fuzz::bytes_of(data, size), "fuzz." VOROCRUST_FUZZ_TEXT(VOROCRUST_FUZZ_FORMAT));
    validate(mesh);
    mesh_info(mesh);
  });
}
