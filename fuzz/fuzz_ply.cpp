// libFuzzer target: the PLY reader (ascii and both binary byte orders; seeded with all three),
// then compute_kernel on what parses. The same bytes also go through read_mesh without a format,
// which fuzzes detect_format and whichever reader it picks.
#include "fuzz_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  kfuzz::fuzz_reader(kergen::read_ply(bytes, "fuzz.ply"), kfuzz::Roundtrip::None);
  kfuzz::check_read_result(kergen::read_mesh(bytes, kergen::MeshFormat::Unknown));
  return 0;
}
