// libFuzzer target: the .node/.ele reader; the input is the .node text, a line "=====", then the
// .ele text (no separator: all .node, empty .ele).
#include "fuzz_volume.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const size_t cut = bytes.find("\n=====\n");
  const std::string_view node = bytes.substr(0, cut);
  const std::string_view ele = cut == std::string_view::npos ? std::string_view() : bytes.substr(cut + 7);
  kfuzz::fuzz_volume(kergen::read_node_ele(node, ele, "fuzz.node", "fuzz.ele"));
  return 0;
}
