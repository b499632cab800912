// libFuzzer target: the OBJ reader (then write/read round trip and compute_kernel on what parses).
#include "fuzz_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  kfuzz::fuzz_reader(kergen::read_obj(bytes, "fuzz.obj"), kfuzz::Roundtrip::Obj);
  return 0;
}
