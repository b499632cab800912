// Hints for hot loops that the native and the wasm build should compile alike.
#pragma once

// Lambdas that GCC inlines natively but clang keeps out of line in the wasm build: there every
// captured variable is then reached through the closure in linear memory, on every call.
// (Native builds are left to their own inlining, which measured no better when forced.)
#if defined(__wasm__)
#define KERGEN_INLINE __attribute__((always_inline))
#else
#define KERGEN_INLINE
#endif

// Function multi-versioning for the vectorized scans: GCC and clang compile an AVX2 clone and a
// baseline one, and the loader picks by CPU (an ifunc: ELF on Linux only; plain code elsewhere,
// in the wasm build and under AddressSanitizer or ThreadSanitizer, whose runtimes are not ready
// when the loader runs the selector). The clones compute the same bits: the library is built with
// -ffp-contract=off, and "avx2" does not enable FMA.
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define KERGEN_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define KERGEN_SANITIZED 1
#endif
#if defined(__x86_64__) && defined(__linux__) && defined(__GNUC__) && !defined(__EMSCRIPTEN__) && \
    !defined(KERGEN_SANITIZED)
#define KERGEN_MULTIVERSION __attribute__((target_clones("avx2", "default")))
#else
#define KERGEN_MULTIVERSION
#endif

namespace kergen {

// A prefetch of the cache line at p. Wasm has no prefetch instruction (__builtin_prefetch
// compiles to nothing there), so an early plain load stands in for it: its result is dropped,
// but the line is on its way while the work before its use goes on. p must be a valid address.
inline void prefetch(const void* p) {
#if defined(__wasm__)
  (void)*static_cast<const volatile char*>(p);
#elif defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}

}  // namespace kergen
