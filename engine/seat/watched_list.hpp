// The block vertices or seat points a seat's system watches for touching: at most
// kMaxSeatClearances indices, held without allocating, since a system is built at every motion
// piece and a record starts one at each of its samples.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <initializer_list>

#include "engine/errors.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

class WatchedList {
 public:
  WatchedList() = default;
  WatchedList(std::initializer_list<int> items) {
    for (const int i : items) push_back(i);
  }
  // Only the indices held are copied (and only they were set): a list is built, copied into its
  // system and kept at each motion piece, and copying or zeroing all it can hold was most of that.
  WatchedList(const WatchedList& other) : size_(other.size_) {
    std::copy_n(other.items_.begin(), size_, items_.begin());
  }
  WatchedList& operator=(const WatchedList& other) {
    size_ = other.size_;
    std::copy_n(other.items_.begin(), size_, items_.begin());
    return *this;
  }

  void push_back(int i) {
    if (size_ == items_.size()) throw ContractViolation("WatchedList: more than it can hold");
    items_[size_++] = i;
  }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const int* begin() const { return items_.data(); }
  const int* end() const { return items_.data() + size_; }
  int operator[](std::size_t k) const { return items_[k]; }
  friend bool operator==(const WatchedList& a, const WatchedList& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  }

 private:
  std::array<int, kMaxSeatClearances> items_;  // the first size_ set
  std::size_t size_ = 0;
};

}  // namespace blockfrag
