// libFuzzer target: the OFF reader (then write/read round trip and compute_kernel on what parses).
#include "fuzz_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  kfuzz::fuzz_reader(kergen::read_off(bytes, "fuzz.off"), kfuzz::Roundtrip::Off);
  return 0;
}
