// vtu_arrays.h — the DataArrays of a VTK XML file (vtu.cpp), private to io/: where each one is
// declared, and their decoding from ascii, inline base64 ("binary") and appended data (raw or
// base64), every count and offset checked against the bytes before use.
//
// Binary layout (VTK File Formats, "XML File Formats": binary and appended data): a header
// (UInt32 or UInt64, the file's header_type) holding the byte count, then the values, in the
// file's byte_order. Base64 data is either the header and the values encoded as one stream or
// each encoded separately (VTK and meshio write either); decoding padded quanta in sequence reads
// both. Compressed data (a `compressor` attribute on VTKFile) is refused, ascii arrays excepted.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace kergen::io::vtu {

// One DataArray as the XML declares it.
struct ArraySpec {
  bool present = false;
  std::string_view type, format;
  long long components = 1;
  bool has_offset = false;
  uint64_t offset = 0;
  size_t tag_at = 0;                    // byte offset of the <DataArray tag
  size_t text_begin = 0, text_end = 0;  // inline content (ascii, binary)
};

// The 1-based line of byte `offset` (only on the way to an error message).
size_t line_at(std::string_view text, size_t offset);

class Decoder {
 public:
  Decoder(std::string_view text, const std::string& name, bool big_endian, bool header64, std::string_view compressor,
          bool appended, bool appended_raw, size_t appended_begin);
  // Appends the array's values; `expected` values exactly unless SIZE_MAX. Non-finite values refused.
  void doubles(const ArraySpec& array, uint64_t expected, std::vector<double>& out);
  // Replaces `out` with the array's values (integer types only); `expected` as above.
  void integers(const ArraySpec& array, uint64_t expected, std::vector<int64_t>& out);

 private:
  [[noreturn]] void fail_array(const ArraySpec& array, const std::string& reason) const;
  // The values' bytes of a binary or appended array (after its header), in file byte order.
  std::string payload(const ArraySpec& array) const;
  std::string base64_payload(const ArraySpec& array, std::string_view encoded, size_t where) const;
  uint64_t header_value(const std::string& bytes) const;
  std::string_view text_;
  const std::string& name_;
  bool big_endian_, header64_;
  std::string_view compressor_;
  bool appended_, appended_raw_;
  size_t appended_begin_;
};

}  // namespace kergen::io::vtu
