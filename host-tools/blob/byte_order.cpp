#include "blob/byte_order.hpp"

#include <cstdint>

namespace spinhash {
namespace host {

ByteOrder native_byte_order() {
  const uint32_t probe = 1u;
  unsigned char first = 0;
  std::memcpy(&first, &probe, 1);
  return first == 1u ? ByteOrder::kLittle : ByteOrder::kBig;
}

ByteOrder resolve_byte_order(ByteOrder order) {
  return order == ByteOrder::kNative ? native_byte_order() : order;
}

ByteOrder opposite_byte_order(ByteOrder order) {
  return resolve_byte_order(order) == ByteOrder::kLittle ? ByteOrder::kBig : ByteOrder::kLittle;
}

const char* byte_order_name(ByteOrder order) {
  switch (order) {
    case ByteOrder::kLittle: return "little-endian";
    case ByteOrder::kBig: return "big-endian";
    case ByteOrder::kNative: return "native";
  }
  return "unknown";
}

}  // namespace host
}  // namespace spinhash
