// SmallVector against std::vector: the same contents after the same operations, inside and
// beyond the inline capacity, through copies and moves.
#include "util/small_vector.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace {

using kergen::SmallVector;
using Small = SmallVector<uint32_t, 4>;

void expect_same(const Small& s, const std::vector<uint32_t>& v) {
  ASSERT_EQ(s.size(), v.size());
  EXPECT_TRUE(s == v);
  for (size_t i = 0; i < v.size(); ++i) EXPECT_EQ(s[i], v[i]) << i;
}

TEST(SmallVector, RandomOperationsMatchStdVector) {
  std::mt19937 rng(3);
  for (int round = 0; round < 200; ++round) {
    Small s;
    std::vector<uint32_t> v;
    for (int op = 0; op < 40; ++op) {
      const uint32_t x = rng() % 100;
      switch (rng() % 5) {
        case 0:
        case 1:
          s.push_back(x);
          v.push_back(x);
          break;
        case 2: {
          const size_t at = v.empty() ? 0 : rng() % (v.size() + 1);
          s.insert(s.begin() + at, x);
          v.insert(v.begin() + long(at), x);
          break;
        }
        case 3:
          if (!v.empty()) {
            const size_t at = rng() % v.size();
            s.erase(s.begin() + at);
            v.erase(v.begin() + long(at));
          }
          break;
        default: {  // copies and moves, inline or on the heap
          Small copy = s;
          Small moved = std::move(copy);
          EXPECT_TRUE(copy.empty());
          s = moved;
          Small other;
          other.push_back(7);
          other = std::move(moved);
          s = std::move(other);
        }
      }
      expect_same(s, v);
    }
  }
}

TEST(SmallVector, AssignFromRangesAndVectors) {
  const std::vector<uint32_t> big = {9, 8, 7, 6, 5, 4, 3, 2, 1};
  Small s(big);
  expect_same(s, big);
  s.assign(big.begin() + 2, big.begin() + 5);
  expect_same(s, {7, 6, 5});
  s.clear();
  EXPECT_TRUE(s.empty());
  s.assign(big.begin(), big.end());
  expect_same(s, big);
  EXPECT_FALSE(s == std::vector<uint32_t>(big.begin(), big.end() - 1));
}

}  // namespace
