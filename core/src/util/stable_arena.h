// StableArena: objects created one at a time and freed all together, at addresses that never
// move (for per-vertex caches that many copies of a vertex point to).
#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

namespace kergen {

// Default-constructed objects in blocks that never move (16 objects, then twice as many each
// time, up to kMaxBlock): a pointer to one stays valid as long as the arena. One allocation per
// block instead of one per object, and no reference counts.
template <class T>
class StableArena {
 public:
  T& emplace() {
    if (used_ == block_size_) {
      block_size_ = blocks_.empty() ? 16 : std::min<size_t>(2 * block_size_, kMaxBlock);
      // Default-initialised (not value-initialised: no zeroing of what each object's
      // constructor leaves to be written, such as an expansion's component buffer).
      blocks_.push_back(std::unique_ptr<T[]>(new T[block_size_]));
      used_ = 0;
    }
    return blocks_.back()[used_++];
  }

 private:
  static constexpr size_t kMaxBlock = 4096;
  std::vector<std::unique_ptr<T[]>> blocks_;
  size_t block_size_ = 0, used_ = 0;
};

}  // namespace kergen
