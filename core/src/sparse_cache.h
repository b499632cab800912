// SparseCache: values computed on demand for a few of many ids, in one flat table.
#pragma once

#include <cstdint>
#include <memory>

#include "flat_map.h"

namespace kergen {

// Objects computed on demand for a few of many planes, by plane id. References stay valid until
// their entry is erased (the objects live on the heap; the table holds pointers).
template <class T>
class SparseCache {
 public:
  T* find(uint32_t id) const {
    const std::unique_ptr<T>* v = table_.find(id);
    return v ? v->get() : nullptr;
  }
  T& insert(uint32_t id, std::unique_ptr<T> v) { return **table_.try_emplace(id, std::move(v)).first; }
  void erase(uint32_t id) { table_.erase(id); }

 private:
  FlatMap<uint32_t, std::unique_ptr<T>, IdentityHash> table_{0xffffffffu};  // (plane ids are below 2^32 - 1)
};

}  // namespace kergen
