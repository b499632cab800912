// StableArena and SparseCache: objects keep their addresses and values while many more are
// added (the vertices' and planes' caches point to them for a whole computation), and the
// cache's find / insert / erase agree with a plain map.
#include "util/stable_arena.h"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <vector>

#include "util/sparse_cache.h"

namespace {

struct Payload {
  std::vector<double> heap;  // an owning member: destroyed with the arena
  int id = -1;
};

TEST(StableArena, AddressesAndValuesSurviveGrowth) {
  kergen::StableArena<Payload> arena;
  std::vector<Payload*> made;
  for (int i = 0; i < 20000; ++i) {  // several blocks, the largest ones capped
    Payload& p = arena.emplace();
    EXPECT_EQ(p.id, -1);  // default-constructed
    EXPECT_TRUE(p.heap.empty());
    p.id = i;
    p.heap.assign(size_t(i % 7), double(i));
    made.push_back(&p);
  }
  for (int i = 0; i < 20000; ++i) {
    ASSERT_EQ(made[size_t(i)]->id, i);
    ASSERT_EQ(made[size_t(i)]->heap.size(), size_t(i % 7));
  }
}

TEST(SparseCache, AgreesWithAMapAndKeepsReferences) {
  kergen::SparseCache<Payload> cache;
  std::map<uint32_t, int> expected;
  std::map<uint32_t, Payload*> where;
  std::mt19937 rng(11);
  for (int op = 0; op < 20000; ++op) {
    const uint32_t id = rng() % 5000;
    if (rng() % 4 == 0) {
      cache.erase(id);
      expected.erase(id);
      where.erase(id);
    } else if (!expected.count(id)) {
      Payload p;
      p.id = op;
      Payload& in = cache.insert(id, std::move(p));
      EXPECT_EQ(in.id, op);
      expected[id] = op;
      where[id] = &in;
    } else {
      Payload p;
      p.id = -7;
      EXPECT_EQ(cache.insert(id, std::move(p)).id, expected[id]);  // an existing entry wins
    }
  }
  for (uint32_t id = 0; id < 6000; ++id) {
    Payload* found = cache.find(id);
    if (!expected.count(id)) {
      EXPECT_EQ(found, nullptr) << id;
      continue;
    }
    ASSERT_NE(found, nullptr) << id;
    EXPECT_EQ(found->id, expected[id]) << id;
    EXPECT_EQ(found, where[id]) << id;  // the address given at insertion
  }
}

}  // namespace
