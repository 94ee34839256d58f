// Byte order of a blob being written, and scalar byte swapping for it.
#pragma once
#include <algorithm>
#include <cstring>
#include <type_traits>

namespace spinhash {
namespace host {

enum class ByteOrder { kLittle, kBig, kNative };

// The order of the machine running this code (never kNative).
ByteOrder native_byte_order();
// kNative becomes the machine's order; the others are returned as they are.
ByteOrder resolve_byte_order(ByteOrder order);
// kLittle <-> kBig (kNative is resolved first).
ByteOrder opposite_byte_order(ByteOrder order);
const char* byte_order_name(ByteOrder order);

// Reverses the bytes of an integer or float.
template <typename T>
T byteswap_scalar(T v) {
  static_assert(std::is_arithmetic<T>::value, "scalars only; swap structs field by field");
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  std::reverse(b, b + sizeof(T));
  std::memcpy(&v, b, sizeof(T));
  return v;
}

template <typename T>
void swap_in_place(T* v, bool swap) {
  if (swap) *v = byteswap_scalar(*v);
}

template <typename T, size_t N>
void swap_array_in_place(T (&v)[N], bool swap) {
  for (T& e : v) swap_in_place(&e, swap);
}

}  // namespace host
}  // namespace spinhash
