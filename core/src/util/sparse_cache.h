// SparseCache: values computed on demand for a few of many ids, in one flat table.
#pragma once

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "util/flat_map.h"

namespace kergen {

// Objects computed on demand for a few of many planes, by plane id. References stay valid until
// their entry is erased: the objects live in blocks that never move (8 objects, then twice as
// many each time), so that a small run's handful of entries costs one or two allocations rather
// than one each; an erased entry's place is reused.
template <class T>
class SparseCache {
 public:
  T* find(uint32_t id) const {
    T* const* v = table_.find(id);
    return v ? *v : nullptr;
  }
  T& insert(uint32_t id, T&& value) {
    if (T* existing = find(id)) return *existing;
    T* slot = take_slot();
    *slot = std::move(value);
    table_.try_emplace(id, slot);
    return *slot;
  }
  void erase(uint32_t id) {
    if (T* v = find(id)) {
      free_.push_back(v);
      table_.erase(id);
    }
  }

 private:
  T* take_slot() {
    if (!free_.empty()) {
      T* slot = free_.back();
      free_.pop_back();
      return slot;
    }
    if (used_ == block_size_) {
      block_size_ = blocks_.empty() ? 8 : 2 * block_size_;
      blocks_.push_back(std::make_unique<T[]>(block_size_));
      used_ = 0;
    }
    return &blocks_.back()[used_++];
  }

  FlatMap<uint32_t, T*, IdentityHash> table_{0xffffffffu};  // (plane ids are below 2^32 - 1)
  std::vector<std::unique_ptr<T[]>> blocks_;
  size_t block_size_ = 0, used_ = 0;
  std::vector<T*> free_;
};

}  // namespace kergen
