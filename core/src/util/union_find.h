// Disjoint sets with path halving; the smaller id becomes the root (deterministic classes).
#pragma once

#include <cstdint>
#include <numeric>
#include <vector>

#include "util/raw_vector.h"

namespace kergen {

struct UnionFind {
  RawVector<uint32_t> parent;  // (iota writes it in full)
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  uint32_t find(uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  bool unite(uint32_t a, uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    if (a < b)
      parent[b] = a;
    else
      parent[a] = b;
    return true;
  }
};

}  // namespace kergen
