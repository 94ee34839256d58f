// Power-of-two hash tables of the core: their capacities and Fibonacci
// hashing into them.
#pragma once
#include <cstdint>

namespace spinhash {

// The smallest power of two at least v (at most 2^31).
inline uint32_t next_pow2(uint32_t v) {
  uint32_t p = 1u;
  while (p < v && p < 0x80000000u) p <<= 1u;  // bounded: at most 31 doublings
  return p;
}

// Fibonacci hashing into a power-of-two table: a key's 32-bit product with
// kFibonacciMultiplier (2^32 / golden ratio), its top log2(capacity) bits
// the slot. No 64-bit arithmetic, which 32-bit targets emulate.
constexpr uint32_t kFibonacciMultiplier = 0x9E3779B1u;
// The product's bits dropped for a power-of-two capacity: 32 - log2(capacity).
inline uint32_t slot_shift(uint32_t capacity) {
  uint32_t shift = 32u;
  for (uint32_t c = capacity; c > 1u; c >>= 1u) --shift;
  return shift;
}
// The slot of hash h in the table: its top bits (slot 0 in a one-slot table).
inline uint32_t slot_of(uint32_t h, uint32_t shift) { return shift < 32u ? h >> shift : 0u; }

}  // namespace spinhash
