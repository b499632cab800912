// The result blocks of bindings.cpp (its header comment has the layout), shared with the batch
// entry (batch_bindings.cpp): a kernel's block, an error's block, the request's option slots,
// and the guard that turns a C++ exception into an error block.
#pragma once

#include <cstdint>
#include <exception>
#include <new>
#include <string>
#include <utility>

#include "kergen/kergen.h"

namespace kergen_wasm {

// A result block (malloc'd; index.js copies it out and frees it) with `code` as the error and
// `message`; 0 when it cannot be allocated.
uintptr_t error_block(const char* code, const std::string& message);

// The result block of a computed kernel (its error's block when it has one); 0 when it cannot be
// allocated.
uintptr_t kernel_block(const kergen::Kernel& kernel);

// The options in the f64 option slots at `request` (NaN = not given).
kergen::Options read_options(uintptr_t request);

// Runs an entry's body: a C++ exception becomes the error block `make_error(code, message)` writes
// (thrown in JS as a KergenError), never a trap that would leave the module unusable. cells.js's
// blocks have their own layout, hence the writer as a parameter.
template <class MakeError, class Body>
uintptr_t guarded_with(MakeError&& make_error, Body&& body) {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    return make_error("OUT_OF_MEMORY", "out of memory (the wasm heap is limited to 4 GB)");
  } catch (const std::exception& e) { return make_error("INTERNAL_ERROR", std::string("internal error: ") + e.what()); }
}

// guarded_with() with this file's error_block().
template <class Body>
uintptr_t guarded(Body&& body) {
  return guarded_with(error_block, std::forward<Body>(body));
}

}  // namespace kergen_wasm
