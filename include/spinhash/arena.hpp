// Bump allocator over a caller-owned buffer (the workspace). With a null
// buffer it only counts, which is how required_workspace_bytes() is computed
// from the very same carving code that recognize() uses.
#pragma once
#include <cstddef>
#include <cstdint>

namespace spinhash {

class Arena {
 public:
  static constexpr size_t kMinAlign = 16;  // enough for Eigen fixed-size loads and doubles

  Arena() = default;
  Arena(void* base, size_t capacity) : base_(static_cast<uint8_t*>(base)), capacity_(capacity) {}

  // n objects of T, uninitialised; nullptr when counting or out of room
  // (then overflowed() is true and used() still grows to the size needed).
  template <typename T>
  T* alloc(size_t n) {
    size_t align = alignof(T) > kMinAlign ? alignof(T) : kMinAlign;
    size_t start = (used_ + align - 1) / align * align;
    if (n > (SIZE_MAX - start) / sizeof(T)) {  // size overflow: unsatisfiable
      overflowed_ = true;
      used_ = SIZE_MAX;
      return nullptr;
    }
    size_t end = start + n * sizeof(T);
    used_ = end;
    if (base_ == nullptr || end > capacity_) {
      overflowed_ = true;
      return nullptr;
    }
    return reinterpret_cast<T*>(base_ + start);
  }

  size_t used() const { return used_; }
  bool overflowed() const { return overflowed_; }

 private:
  uint8_t* base_ = nullptr;
  size_t capacity_ = 0;
  size_t used_ = 0;
  bool overflowed_ = false;
};

}  // namespace spinhash
