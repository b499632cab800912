// A flat hash set of 64-bit keys for the hot paths (a node-based std::unordered_set paid one
// heap allocation per key, which on small meshes cost more than the geometry).
#pragma once

#include <cassert>
#include <cstdint>
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

}  // namespace kergen
