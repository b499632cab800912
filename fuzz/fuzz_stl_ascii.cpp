// libFuzzer target: the STL reader on text (seeded with ascii STL; the reader decides ascii vs
// binary by content, so this also reaches the binary path), then compute_kernel on what parses.
#include "fuzz_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  kfuzz::fuzz_reader(kergen::read_stl(bytes, "fuzz.stl"), kfuzz::Roundtrip::None);
  return 0;
}
