// Flat containers for the hot paths: node-based standard containers paid one heap allocation
// per key, which on small meshes cost more than the geometry.
#pragma once

#include <cassert>
#include <cstdint>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace kergen {

// Set of 64-bit keys in one flat array (open addressing, linear probing): the hot loops insert
// and probe ids packed into 64 bits. ~0 is reserved as the empty slot.
class U64Set {
 public:
  static constexpr uint64_t kEmpty = ~uint64_t(0);

  // Room for n keys without regrowth.
  explicit U64Set(size_t n = 0) { rehash(capacity_for(n)); }

  bool contains(uint64_t x) const {
    for (size_t i = slot(x);; i = (i + 1) & mask_) {
      if (slots_[i] == x) return true;
      if (slots_[i] == kEmpty) return false;
    }
  }
  // Returns false when x was already present.
  bool insert(uint64_t x) {
    assert(x != kEmpty && "~0 marks empty slots");
    if (2 * (size_ + 1) > slots_.size()) rehash(2 * slots_.size());
    return place(x);
  }
  size_t size() const { return size_; }

 private:
  static size_t capacity_for(size_t n) {
    size_t cap = 16;
    while (cap < 2 * n + 16) cap <<= 1;
    return cap;
  }
  size_t slot(uint64_t x) const { return size_t((x * 0x9E3779B97F4A7C15ull) >> 32) & mask_; }
  bool place(uint64_t x) {
    for (size_t i = slot(x);; i = (i + 1) & mask_) {
      if (slots_[i] == x) return false;
      if (slots_[i] == kEmpty) {
        slots_[i] = x;
        ++size_;
        return true;
      }
    }
  }
  void rehash(size_t cap) {
    std::vector<uint64_t> old;
    old.swap(slots_);
    slots_.assign(cap, kEmpty);
    mask_ = cap - 1;
    size_ = 0;
    for (uint64_t x : old)
      if (x != kEmpty) place(x);
  }

  std::vector<uint64_t> slots_;
  size_t mask_ = 0;
  size_t size_ = 0;
};

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

// Objects computed on demand for a few of many planes, by plane id (open addressing, linear
// probing, backward-shift erase). References stay valid until their entry is erased.
template <class T>
class SparseCache {
 public:
  T* find(uint32_t id) const {
    if (size_ == 0) return nullptr;
    for (size_t i = home(id);; i = (i + 1) & mask_) {
      if (keys_[i] == id) return vals_[i].get();
      if (keys_[i] == kEmpty) return nullptr;
    }
  }
  T& insert(uint32_t id, std::unique_ptr<T> v) {
    if (2 * (size_ + 1) > keys_.size()) grow();
    size_t i = home(id);
    while (keys_[i] != kEmpty) i = (i + 1) & mask_;
    keys_[i] = id;
    vals_[i] = std::move(v);
    ++size_;
    return *vals_[i];
  }
  void erase(uint32_t id) {
    if (size_ == 0) return;
    size_t j = home(id);
    while (keys_[j] != id) {
      if (keys_[j] == kEmpty) return;
      j = (j + 1) & mask_;
    }
    --size_;
    for (;;) {
      keys_[j] = kEmpty;
      vals_[j].reset();
      size_t k = j;
      for (;;) {
        k = (k + 1) & mask_;
        if (keys_[k] == kEmpty) return;
        const size_t h = home(keys_[k]);
        // An entry may move back to j unless its home lies cyclically in (j, k].
        if (j < k ? (h <= j || h > k) : (h <= j && h > k)) break;
      }
      keys_[j] = keys_[k];
      vals_[j] = std::move(vals_[k]);
      j = k;
    }
  }

 private:
  static constexpr uint32_t kEmpty = 0xffffffffu;
  size_t home(uint32_t id) const { return size_t((uint64_t(id) * 0x9E3779B97F4A7C15ull) >> 32) & mask_; }
  void grow() {
    std::vector<uint32_t> keys(keys_.empty() ? 16 : 2 * keys_.size(), kEmpty);
    std::vector<std::unique_ptr<T>> vals(keys.size());
    keys.swap(keys_);
    vals.swap(vals_);
    mask_ = keys_.size() - 1;
    for (size_t i = 0; i < keys.size(); ++i) {
      if (keys[i] == kEmpty) continue;
      size_t j = home(keys[i]);
      while (keys_[j] != kEmpty) j = (j + 1) & mask_;
      keys_[j] = keys[i];
      vals_[j] = std::move(vals[i]);
    }
  }
  std::vector<uint32_t> keys_;
  std::vector<std::unique_ptr<T>> vals_;
  size_t size_ = 0, mask_ = 0;
};

}  // namespace kergen
