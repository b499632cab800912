// libFuzzer target: the VTU reader (then compute_cell_kernels and the VTU writer's round trip).
#include "fuzz_volume.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  kfuzz::fuzz_volume(kergen::read_vtu(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.vtu"));
  return 0;
}
