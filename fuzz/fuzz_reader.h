// Shared body of the reader fuzz targets: parse the bytes; whatever parses must be a well-formed
// mesh, must survive a write/read round trip bit for bit, and is handed to compute_kernel (with a
// small face limit so one run stays fast), whose result must pass the invariants.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "invariants.h"
#include "kergen/io.h"
#include "kergen/kergen.h"

namespace kfuzz {

inline void check_read_result(const kergen::ReadResult& r) {
  using kergen::Error;
  if (!r.ok()) {
    KFUZZ_CHECK(r.error == Error::ParseError || r.error == Error::EmptyInput || r.error == Error::TooLarge ||
                    r.error == Error::IoError,
                std::string("reader returned ") + kergen::error_name(r.error));
    KFUZZ_CHECK(!r.message.empty(), "reader error without a message");
    KFUZZ_CHECK(r.message.size() < 4096, "reader message of " + std::to_string(r.message.size()) + " bytes");
    return;
  }
  const kergen::Mesh& m = r.mesh;
  KFUZZ_CHECK(m.positions.size() % 3 == 0, "positions not xyz triples");
  for (double c : m.positions) KFUZZ_CHECK(std::isfinite(c), "reader accepted a non-finite coordinate");
  size_t sum = 0;
  if (m.face_sizes.empty()) {
    KFUZZ_CHECK(m.indices.size() % 3 == 0, "triangle indices not a multiple of 3");
  } else {
    for (uint32_t s : m.face_sizes) sum += s;
    KFUZZ_CHECK(sum == m.indices.size(), "face_sizes do not add up to the index count");
  }
  for (uint32_t v : m.indices) KFUZZ_CHECK(v < m.num_vertices(), "reader accepted an out-of-range index");
}

inline bool same_mesh(const kergen::Mesh& a, const kergen::Mesh& b) {
  if (a.positions.size() != b.positions.size() || a.indices != b.indices) return false;
  for (size_t i = 0; i < a.positions.size(); ++i)
    if (std::memcmp(&a.positions[i], &b.positions[i], sizeof(double)) != 0) return false;
  const bool ta = a.face_sizes.empty(), tb = b.face_sizes.empty();
  if (ta && tb) return true;
  // One side may list every size explicitly (all 3) where the other leaves it implicit.
  std::vector<uint32_t> fa = a.face_sizes, fb = b.face_sizes;
  if (ta) fa.assign(a.indices.size() / 3, 3);
  if (tb) fb.assign(b.indices.size() / 3, 3);
  return fa == fb;
}

inline void run_kernel_on(const kergen::Mesh& m) {
  if (m.num_faces() == 0) return;
  kergen::Options o;
  o.max_faces = 3000;
  o.max_vertices = 10000;
  const kergen::Kernel k = kergen::compute_kernel(m.view(), o);
  if (m.num_faces() > o.max_faces || m.num_vertices() > o.max_vertices) {
    KFUZZ_CHECK(k.error == kergen::Error::TooLarge, std::string("over the limits but ") + kergen::error_name(k.error));
    return;
  }
  check_kernel(m.view(), k, false, true);
}

enum class Roundtrip { Off, Obj, None };

inline void fuzz_reader(const kergen::ReadResult& r, Roundtrip rt) {
  check_read_result(r);
  if (!r.ok()) return;
  if (rt == Roundtrip::Off) {
    const kergen::ReadResult back = kergen::read_off(kergen::write_off(r.mesh), "roundtrip.off");
    KFUZZ_CHECK(back.ok(), "write_off output does not read back: " + back.message);
    KFUZZ_CHECK(same_mesh(back.mesh, r.mesh), "OFF round trip changed the mesh");
  } else if (rt == Roundtrip::Obj) {
    const kergen::ReadResult back = kergen::read_obj(kergen::write_obj(r.mesh), "roundtrip.obj");
    KFUZZ_CHECK(back.ok(), "write_obj output does not read back: " + back.message);
    KFUZZ_CHECK(same_mesh(back.mesh, r.mesh), "OBJ round trip changed the mesh");
  }
  run_kernel_on(r.mesh);
}

}  // namespace kfuzz
