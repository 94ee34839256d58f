// An owning byte buffer aligned to kBufferAlignment (64), as Database::open
// requires. std::vector<uint8_t> only promises the alignment of new[].
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace spinhash {
namespace host {

class AlignedBytes {
 public:
  AlignedBytes() = default;
  explicit AlignedBytes(size_t size);  // zero-filled; size 0 holds nothing
  static AlignedBytes copy_of(const uint8_t* data, size_t size);
  static AlignedBytes copy_of(const std::vector<uint8_t>& bytes) {
    return copy_of(bytes.data(), bytes.size());
  }

  uint8_t* data() { return bytes_.get(); }
  const uint8_t* data() const { return bytes_.get(); }
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0u; }

 private:
  struct AlignedDelete {
    void operator()(uint8_t* p) const;
  };
  std::unique_ptr<uint8_t, AlignedDelete> bytes_;
  size_t size_ = 0;
};

}  // namespace host
}  // namespace spinhash
