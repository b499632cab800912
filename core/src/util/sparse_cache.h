// SparseCache: values computed on demand for some of many ids, found through a dense table.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace kergen {

// Objects computed on demand for some of many ids (planes), found by id through a dense table
// of pointers (8 bytes per id up to the largest one inserted: a lookup is one load, where a hash
// table's probe was a share of every filtered predicate's cost on dense kernels). References
// stay valid until their entry is erased: the objects live in blocks that never move (8
// objects, then twice as many each time, up to 1024), so that a small run's handful of entries costs one or
// two allocations rather than one each; an erased entry's place is reused.
template <class T>
class SparseCache {
 public:
  T* find(uint32_t id) const { return id < table_.size() ? table_[id] : nullptr; }
  T& insert(uint32_t id, T&& value) {
    if (T* existing = find(id)) return *existing;
    T* slot = take_slot();
    *slot = std::move(value);
    if (id >= table_.size()) table_.resize(std::max<size_t>(size_t(id) + 1, 2 * table_.size()), nullptr);
    table_[id] = slot;
    return *slot;
  }
  void erase(uint32_t id) {
    if (T* v = find(id)) {
      free_.push_back(v);
      table_[id] = nullptr;
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
      block_size_ = blocks_.empty() ? 8 : std::min<size_t>(2 * block_size_, 1024);
      blocks_.push_back(std::unique_ptr<T[]>(new T[block_size_]));  // default-initialised: no zeroing
      used_ = 0;
    }
    return &blocks_.back()[used_++];
  }

  std::vector<T*> table_;
  std::vector<std::unique_ptr<T[]>> blocks_;
  size_t block_size_ = 0, used_ = 0;
  std::vector<T*> free_;
};

}  // namespace kergen
