// SparseCache: values computed on demand for a few of many ids, in one flat table.
#pragma once

#include <cassert>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace kergen {

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
