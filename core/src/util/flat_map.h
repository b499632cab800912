// The core's one general hash table: open addressing with linear probing in flat arrays (a
// node-based std::unordered_map paid one heap allocation per key, which on small meshes cost
// more than the geometry). Three tables stay specialised, for reasons of their own: PointTable
// (point_table.h: ids keyed by positions held in the caller's array, prefetched a block ahead),
// plane_classes' (32-bit hash slots heading chains of candidates, prefetched likewise) and the
// tracer's vertex index (keyed by a set of plane ids it compares in place).
#pragma once

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace kergen {

// Key -> Value. `Hash` maps a key to 64 bits (mixed again here, so an identity hash is fine);
// one key value, `empty_key`, is reserved to mark free slots and must never be inserted. At most
// half full; growing moves the values, so pointers returned earlier are then invalid. Nothing is
// allocated before the first insertion unless room for `n` keys is asked for.
template <class Key, class Value, class Hash, class Eq = std::equal_to<Key>>
class FlatMap {
 public:
  explicit FlatMap(const Key& empty_key, size_t n = 0) : empty_(empty_key) {
    if (n > 0) rehash(capacity_for(n));
  }

  Value* find(const Key& key) {
    if (size_ == 0) return nullptr;
    for (size_t i = slot(key);; i = (i + 1) & mask_) {
      if (eq_(keys_[i], key)) return &values_[i];
      if (eq_(keys_[i], empty_)) return nullptr;
    }
  }
  const Value* find(const Key& key) const { return const_cast<FlatMap*>(this)->find(key); }
  bool contains(const Key& key) const { return find(key) != nullptr; }

  // The value of `key`, inserted as `value` when absent; second: whether it was inserted.
  std::pair<Value*, bool> try_emplace(const Key& key, Value value) {
    assert(!eq_(key, empty_) && "the empty key marks free slots");
    if (2 * (size_ + 1) > keys_.size()) rehash(keys_.empty() ? 16 : 2 * keys_.size());
    return place(key, std::move(value));
  }

  // Removes `key` if present (backward-shift deletion: no tombstones, probes stay short).
  void erase(const Key& key) {
    if (size_ == 0) return;
    size_t j = slot(key);
    while (!eq_(keys_[j], key)) {
      if (eq_(keys_[j], empty_)) return;
      j = (j + 1) & mask_;
    }
    --size_;
    for (;;) {
      keys_[j] = empty_;
      values_[j] = Value();
      size_t k = j;
      for (;;) {
        k = (k + 1) & mask_;
        if (eq_(keys_[k], empty_)) return;
        const size_t home = slot(keys_[k]);
        // The entry at k may move back to j unless its home lies cyclically in (j, k].
        if (j < k ? (home <= j || home > k) : (home <= j && home > k)) break;
      }
      keys_[j] = keys_[k];
      values_[j] = std::move(values_[k]);
      j = k;
    }
  }

  size_t size() const { return size_; }

 private:
  static size_t capacity_for(size_t n) {
    size_t cap = 16;
    while (cap < 2 * n + 16) cap <<= 1;
    return cap;
  }
  size_t slot(const Key& key) const { return size_t((uint64_t(hash_(key)) * 0x9E3779B97F4A7C15ull) >> 32) & mask_; }
  std::pair<Value*, bool> place(const Key& key, Value&& value) {
    for (size_t i = slot(key);; i = (i + 1) & mask_) {
      if (eq_(keys_[i], key)) return {&values_[i], false};
      if (eq_(keys_[i], empty_)) {
        keys_[i] = key;
        values_[i] = std::move(value);
        ++size_;
        return {&values_[i], true};
      }
    }
  }
  void rehash(size_t cap) {
    std::vector<Key> old_keys(cap, empty_);
    std::vector<Value> old_values(cap);
    old_keys.swap(keys_);  // keys_ and values_ are now the new, free arrays
    old_values.swap(values_);
    mask_ = cap - 1;
    size_ = 0;
    for (size_t i = 0; i < old_keys.size(); ++i)
      if (!eq_(old_keys[i], empty_)) place(old_keys[i], std::move(old_values[i]));
  }

  Key empty_;
  Hash hash_;
  Eq eq_;
  std::vector<Key> keys_;
  std::vector<Value> values_;
  size_t mask_ = 0;
  size_t size_ = 0;
};

// 64-bit keys hash as themselves (FlatMap mixes them).
struct IdentityHash {
  uint64_t operator()(uint64_t x) const { return x; }
};

// A set of 64-bit keys (~0 reserved): ids packed into 64 bits in the hot loops.
class U64Set {
 public:
  static constexpr uint64_t kEmpty = ~uint64_t(0);
  explicit U64Set(size_t n = 0) : map_(kEmpty, n) {}
  bool contains(uint64_t x) const { return map_.contains(x); }
  // Returns false when x was already present.
  bool insert(uint64_t x) { return map_.try_emplace(x, 0).second; }
  size_t size() const { return map_.size(); }

 private:
  FlatMap<uint64_t, char, IdentityHash> map_;
};

}  // namespace kergen
