#include "blob/aligned_bytes.hpp"

#include <cstring>
#include <new>

#include "spinhash/limits.hpp"

namespace spinhash {
namespace host {
namespace {
constexpr std::align_val_t kAlignment{kBufferAlignment};
}  // namespace

void AlignedBytes::AlignedDelete::operator()(uint8_t* p) const { ::operator delete(p, kAlignment); }

AlignedBytes::AlignedBytes(size_t size) : size_(size) {
  if (size == 0u) return;
  bytes_.reset(static_cast<uint8_t*>(::operator new(size, kAlignment)));
  std::memset(bytes_.get(), 0, size);
}

AlignedBytes AlignedBytes::copy_of(const uint8_t* data, size_t size) {
  AlignedBytes b(size);
  if (size != 0u) std::memcpy(b.data(), data, size);
  return b;
}

}  // namespace host
}  // namespace spinhash
