// A monotone priority queue of (double level, cell) for the Priority-Flood
// (flow.cpp), whose pops never decrease (every push is at or above the last
// pop): a radix heap (Ahuja, Mehlhorn, Orlin & Tarjan 1990) on the level's
// order-preserving 64 bits, amortised O(1) per operation where a binary heap
// costs O(log n). Equal levels come out in the order they went in:
// deterministic.
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

namespace mcmd::morph {

class RadixHeap {
 public:
  bool empty() const { return size_ == 0; }

  // Empty, ready for pushes at any level (keeps the buckets' capacity).
  void clear() {
    for (auto& b : bucket_) b.clear();
    filled_ = last_ = 0;
    next_ = size_ = 0;
  }

  // Pre: level >= the level of the last pop; not NaN.
  void push(double level, std::int32_t cell) {
    put({key(level), cell});
    ++size_;
  }

  // The lowest (level, cell). Pre: !empty().
  std::pair<double, std::int32_t> pop() {
    if (bucket_[0].empty()) refill();
    const Item it = bucket_[0][next_++];
    if (next_ == bucket_[0].size()) bucket_[0].clear(), next_ = 0;
    --size_;
    return {level_of(it.key), it.cell};
  }

 private:
  struct Item {
    std::uint64_t key;
    std::int32_t cell;
  };

  // Doubles to unsigned integers in the same order (negative numbers too).
  static std::uint64_t key(double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return (b >> 63) ? ~b : b | (std::uint64_t{1} << 63);
  }
  static double level_of(std::uint64_t k) {
    const std::uint64_t b = (k >> 63) ? k & ~(std::uint64_t{1} << 63) : ~k;
    double v;
    std::memcpy(&v, &b, sizeof v);
    return v;
  }
  // Bucket i >= 1 holds keys whose highest bit differing from last_ is bit i - 1.
  int bucket_of(std::uint64_t k) const { return k == last_ ? 0 : 64 - std::countl_zero(k ^ last_); }

  // Into the bucket of its key relative to last_, marked filled.
  void put(const Item& it) {
    const int b = bucket_of(it.key);
    bucket_[b].push_back(it);
    if (b > 0) filled_ |= std::uint64_t{1} << (b - 1);
  }

  // Moves the smallest keys' bucket down: its minimum becomes last_, and
  // its items go to the buckets relative to it (in their order).
  void refill() {
    const int i = std::countr_zero(filled_) + 1;
    std::uint64_t lo = bucket_[i][0].key;
    for (const Item& it : bucket_[i]) lo = std::min(lo, it.key);
    last_ = lo;
    moving_.swap(bucket_[i]);  // the emptied bucket keeps the scratch's capacity
    filled_ &= ~(std::uint64_t{1} << (i - 1));  // its items all go lower
    for (const Item& it : moving_) put(it);
    moving_.clear();
  }

  std::array<std::vector<Item>, 65> bucket_;
  std::vector<Item> moving_;  // refill's scratch, reused: no allocation per refill
  std::uint64_t filled_ = 0;  // bit i - 1: bucket i (>= 1) holds items
  std::uint64_t last_ = 0;
  std::size_t next_ = 0;  // read position in bucket_[0]
  std::size_t size_ = 0;
};

}  // namespace mcmd::morph
