// The result blocks of bindings.cpp (its header comment has the layout), shared with the batch
// entry (batch_bindings.cpp): a kernel's block, an error's block, the request's option slots,
// and the guard that turns a C++ exception into an error block.
#pragma once

#include <cstdint>
#include <exception>
#include <new>
#include <string>

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

// Runs an entry's body: a C++ exception becomes an error block (thrown in JS as a KergenError),
// never a trap that would leave the module unusable.
template <class Body>
uintptr_t guarded(Body&& body) {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    return error_block("OUT_OF_MEMORY", "out of memory (the wasm heap is limited to 4 GB)");
  } catch (const std::exception& e) {
    return error_block("INTERNAL_ERROR", std::string("internal error: ") + e.what());
  }
}

}  // namespace kergen_wasm
