// A vector of a trivially copyable type with room for N elements inside the object: no heap
// allocation until it grows past N. For the short lists of the tracer and the cutter (the
// planes through a vertex or along an edge, the edges at a vertex), which are almost always a
// handful and were, as std::vector, a large share of the allocations on small kernels.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <type_traits>
#include <vector>

namespace kergen {

template <class T, uint32_t N>
class SmallVector {
  static_assert(std::is_trivially_copyable<T>::value, "elements are moved with memcpy");

 public:
  using value_type = T;
  using iterator = T*;
  using const_iterator = const T*;

  SmallVector() = default;
  SmallVector(const SmallVector& o) { assign(o.begin(), o.end()); }
  SmallVector(SmallVector&& o) noexcept { take(o); }
  SmallVector(const std::vector<T>& v) { assign(v.begin(), v.end()); }  // NOLINT: the tracer's scratch lists convert
  SmallVector& operator=(const SmallVector& o) {
    if (this != &o) assign(o.begin(), o.end());
    return *this;
  }
  SmallVector& operator=(SmallVector&& o) noexcept {
    if (this != &o) {
      release();
      take(o);
    }
    return *this;
  }
  ~SmallVector() { release(); }

  template <class It>
  void assign(It first, It last) {
    const size_t n = size_t(std::distance(first, last));
    size_ = 0;
    reserve(n);
    std::copy(first, last, data_);
    size_ = uint32_t(n);
  }
  void reserve(size_t n) {
    if (n > cap_) grow(n);
  }
  void clear() { size_ = 0; }
  void push_back(const T& x) {
    if (size_ == cap_) grow(2 * size_t(cap_));
    data_[size_++] = x;
  }
  iterator insert(const_iterator pos, const T& x) {
    const size_t i = size_t(pos - data_);
    if (size_ == cap_) grow(2 * size_t(cap_));
    std::memmove(data_ + i + 1, data_ + i, (size_ - i) * sizeof(T));
    data_[i] = x;
    ++size_;
    return data_ + i;
  }
  iterator erase(const_iterator pos) {
    const size_t i = size_t(pos - data_);
    std::memmove(data_ + i, data_ + i + 1, (size_ - i - 1) * sizeof(T));
    --size_;
    return data_ + i;
  }

  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }
  T& operator[](size_t i) { return data_[i]; }
  const T& operator[](size_t i) const { return data_[i]; }
  T& back() { return data_[size_ - 1]; }
  const T& back() const { return data_[size_ - 1]; }

 private:
  void grow(size_t n) {
    n = std::max(n, size_t(2) * cap_);
    T* p = new T[n];
    std::memcpy(p, data_, size_ * sizeof(T));
    if (data_ != inline_) delete[] data_;
    data_ = p;
    cap_ = uint32_t(n);
  }
  void release() {
    if (data_ != inline_) delete[] data_;
    data_ = inline_;
    cap_ = N;
  }
  // Takes o's elements (its buffer when on the heap) and leaves it empty; *this holds nothing.
  void take(SmallVector& o) {
    if (o.data_ == o.inline_) {
      std::memcpy(inline_, o.inline_, o.size_ * sizeof(T));
      data_ = inline_;
      cap_ = N;
    } else {
      data_ = o.data_;
      cap_ = o.cap_;
      o.data_ = o.inline_;
      o.cap_ = N;
    }
    size_ = o.size_;
    o.size_ = 0;
  }

  T* data_ = inline_;
  uint32_t size_ = 0, cap_ = N;
  T inline_[N];
};

template <class T, uint32_t N, class Range>
bool operator==(const SmallVector<T, N>& a, const Range& b) {
  return a.size() == size_t(std::end(b) - std::begin(b)) && std::equal(a.begin(), a.end(), std::begin(b));
}

}  // namespace kergen
