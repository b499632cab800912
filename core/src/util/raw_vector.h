// RawVector: a std::vector whose resize leaves new elements uninitialised.
#pragma once

#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace kergen {

// A vector whose resize leaves new elements uninitialised (for arrays written in full right
// after: value-initialising them would be one more pass over fresh memory).
template <class T>
struct NoInitAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = NoInitAllocator<U>;
  };
  NoInitAllocator() = default;
  template <class U>
  NoInitAllocator(const NoInitAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};
template <class T>
using RawVector = std::vector<T, NoInitAllocator<T>>;

}  // namespace kergen
