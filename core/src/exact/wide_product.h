// Full 128-bit products of 64-bit integers for the exact stage of orient3d. WebAssembly has no
// 64x64->128 multiply: there __int128 products become calls to a general 128x128 routine
// (__multi3), and four 32x32->64 products inline are cheaper. Both forms are compiled everywhere
// (the portable one under its own name) so that native tests check the one wasm runs.
#pragma once

#include <cstdint>

namespace kergen {
namespace exact {

using Int128 = __int128;
using UInt128 = unsigned __int128;

// Signed operands by their two's complement: with a = ua - 2^64 [a < 0] (ua = uint64_t(a)),
// a b = ua ub - 2^64 ([a < 0] ub + [b < 0] ua) modulo 2^128, which is a b exactly when
// |a b| < 2^127 (the conversion of UInt128 to Int128 is modular in GCC and Clang).
inline UInt128 portable_wide_product(uint64_t a, uint64_t b) {
  constexpr uint64_t kLow32 = 0xffffffffu;
  const uint64_t a0 = a & kLow32, a1 = a >> 32, b0 = b & kLow32, b1 = b >> 32;
  const uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
  const uint64_t middle = (p00 >> 32) + (p01 & kLow32) + (p10 & kLow32);  // < 3 2^32
  const uint64_t low = (middle << 32) | (p00 & kLow32);
  const uint64_t high = p11 + (p01 >> 32) + (p10 >> 32) + (middle >> 32);
  return (UInt128(high) << 64) | low;
}
inline Int128 portable_wide_product(int64_t a, int64_t b) {
  const uint64_t ua = uint64_t(a), ub = uint64_t(b);
  const uint64_t correction = (a < 0 ? ub : 0) + (b < 0 ? ua : 0);
  return Int128(portable_wide_product(ua, ub) - (UInt128(correction) << 64));
}
inline Int128 portable_wide_product(int64_t a, uint64_t b) {  // |a b| < 2^127
  return Int128(portable_wide_product(uint64_t(a), b) - (UInt128(a < 0 ? b : 0) << 64));
}

#if defined(__wasm__) || defined(KERGEN_PORTABLE_WIDE_PRODUCT)
inline Int128 wide_product(int64_t a, int64_t b) { return portable_wide_product(a, b); }
inline Int128 wide_product(int64_t a, uint64_t b) { return portable_wide_product(a, b); }
#else
inline Int128 wide_product(int64_t a, int64_t b) { return Int128(a) * b; }
inline Int128 wide_product(int64_t a, uint64_t b) { return Int128(a) * Int128(b); }  // |a b| < 2^127
#endif

}  // namespace exact
}  // namespace kergen
