// libFuzzer target: the legacy VTK reader (then compute_cell_kernels and the VTU round trip).
#include "fuzz_volume.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  kfuzz::fuzz_volume(kergen::read_vtk_legacy(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.vtk"));
  return 0;
}
