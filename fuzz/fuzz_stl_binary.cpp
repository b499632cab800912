// libFuzzer target: binary STL. The first input byte chooses how the triangle count in the header
// is set: as the fuzzer wrote it (a count that may lie about the size), or fixed up to match the
// size (so mutations reach the facet decoding and welding instead of the size check), or off by
// one. Then compute_kernel on what parses. The STL writer's output must read back as the same
// triangles.
#include <cstring>
#include <string>

#include "fuzz_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const uint8_t mode = data[0];
  std::string bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  if (mode % 4 != 0 && bytes.size() >= 84) {
    uint64_t n = (bytes.size() - 84) / 50;
    bytes.resize(84 + 50 * n);
    if (mode % 4 == 2) n += 1;           // claims one more triangle than present
    if (mode % 4 == 3) n = 0xffffffffu;  // claims the maximum
    const uint32_t count = static_cast<uint32_t>(n);
    std::memcpy(&bytes[80], &count, 4);  // little-endian hosts only (x86, wasm)
  }
  const kergen::ReadResult r = kergen::read_stl(bytes, "fuzz.stl");
  kfuzz::check_read_result(r);
  if (!r.ok()) return 0;
  // Binary STL stores floats: a mesh read from one writes back and reads back identically.
  const kergen::ReadResult back = kergen::read_stl(kergen::write_stl_binary(r.mesh), "roundtrip.stl");
  KFUZZ_CHECK(back.ok(), "write_stl_binary output does not read back: " + back.message);
  bool all_float = true;
  for (double c : r.mesh.positions) all_float &= double(float(c)) == c;
  if (all_float) {
    KFUZZ_CHECK(back.mesh.num_faces() == r.mesh.num_faces(), "STL round trip changed the triangle count");
  }
  kfuzz::run_kernel_on(r.mesh);
  return 0;
}
