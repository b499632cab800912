// PointTable: vertex ids keyed by their exact positions, for the STL readers' weld (io/stl.cpp) and
// validation's check for two vertices at one position (mesh_prep.cpp).
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

#include "util/compiler_hints.h"

namespace kergen {

// Ids in one flat array (open addressing, linear probing, load factor <= 1/2); the positions
// themselves stay in the caller's xyz array, indexed by id. A slot holds the id and 32 bits of its
// point's hash (bits the slot's place does not come from), so a probe past another point's slot
// reads that point's position only when those bits agree: almost never. Coordinates compare with ==, so -0
// and +0 are one position (and hash alike). On big meshes the table and the positions are larger
// than the caches and every lookup misses: callers hash a block of points ahead, prefetch their
// slots (prefetch_slot), then look them up in order (find_or_insert), which keeps ids in
// first-seen order whatever the block size.
class PointTable {
 public:
  static constexpr uint32_t kEmpty = 0xffffffffu;  // no id (ids are below it)

  // Room for `expected` points without regrowth.
  explicit PointTable(size_t expected) { reset(capacity_for(expected)); }

  // The hash of a position (the high bits depend on every input bit).
  static uint64_t hash(const double* p) {
    uint64_t h = 0;
    for (int k = 0; k < 3; ++k) {
      const double x = p[k] + 0.0;  // -0 + 0 = +0: equal coordinates hash alike
      uint64_t b;
      std::memcpy(&b, &x, sizeof b);
      h = (h ^ b ^ (b >> 29)) * 0x9e3779b97f4a7c15ull;
    }
    return h;
  }
  void prefetch_slot(uint64_t h) const { prefetch(slots_.data() + home(h)); }
  // The second step ahead of a lookup, once its slot has arrived: the position of the id held
  // there (the first one find_or_insert compares with).
  void prefetch_held(const double* pts, uint64_t h) const {
    const uint64_t held = slots_[home(h)];
    if (held != kEmptySlot) prefetch(pts + 3 * size_t(uint32_t(held)));
  }

  // The id of an inserted point at p's position, or kEmpty.
  uint32_t find(const double* pts, const double* p, uint64_t h) const {
    for (size_t slot = home(h);; slot = (slot + 1) & mask_) {
      const uint64_t held = slots_[slot];
      if (held == kEmptySlot) return kEmpty;
      if (same_point(pts, held, p, h)) return uint32_t(held);
    }
  }
  // The id of an inserted point at p's position; if there is none, `id` is inserted and returned.
  // pts[3 i .. 3 i + 2] must hold the position of every id i inserted before (p need not be in
  // pts yet); h = hash(p).
  KERGEN_INLINE uint32_t find_or_insert(const double* pts, const double* p, uint64_t h, uint32_t id) {
    if (2 * (size_ + 1) > slots_.size()) grow(pts);
    for (size_t slot = home(h);; slot = (slot + 1) & mask_) {
      const uint64_t held = slots_[slot];
      if (held == kEmptySlot) {
        slots_[slot] = uint64_t(tag(h)) << 32 | id;
        ++size_;
        return id;
      }
      if (same_point(pts, held, p, h)) return uint32_t(held);
    }
  }

 private:
  static size_t capacity_for(size_t n) {
    size_t cap = 16;
    while (cap < 2 * n + 2) cap <<= 1;
    return cap;
  }
  static constexpr uint64_t kEmptySlot = ~uint64_t(0);  // (its id part is kEmpty)
  size_t home(uint64_t h) const { return size_t(h >> shift_); }
  static uint32_t tag(uint64_t h) { return uint32_t(h); }
  static bool same_point(const double* pts, uint64_t held, const double* p, uint64_t h) {
    if (uint32_t(held >> 32) != tag(h)) return false;
    const double* q = pts + 3 * size_t(uint32_t(held));
    return p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
  }
  void reset(size_t cap) {
    slots_.assign(cap, kEmptySlot);
    mask_ = cap - 1;
    shift_ = 64;
    while ((size_t(1) << (64 - shift_)) < cap) --shift_;
    size_ = 0;
  }
  void grow(const double* pts) {
    std::vector<uint64_t> old;
    old.swap(slots_);
    reset(2 * old.size());
    for (uint64_t held : old)
      if (held != kEmptySlot) {
        const uint32_t id = uint32_t(held);
        find_or_insert(pts, pts + 3 * size_t(id), hash(pts + 3 * size_t(id)), id);
      }
  }

  std::vector<uint64_t> slots_;  // tag << 32 | id, or kEmptySlot
  size_t mask_ = 0;
  int shift_ = 64;
  size_t size_ = 0;
};

}  // namespace kergen
